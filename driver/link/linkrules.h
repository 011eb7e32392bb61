#pragma once
// The link's rules about the unit's command index (docs/gve-protocol.md §8), apart from the
// engine that follows them: which commands must arrive exactly once and how each moves the index.

#include "protocol/command.h"

namespace frezka::driver {

// How far a packet of n commands advances the unit's index once its *E has arrived: every line
// (*S, the commands, *E) is a command (adopted reading §8). One place, to change with hardware.
int packetIndexAdvance(int commandCount);
// Commands whose repetition would change what the machine does (motion, XU/XD, K/R, G, W, J,
// packets): recovered through the index. All others are resent as they are after a lost reply.
bool mustArriveOnce(protocol::Op op);
// Whether a command advances the unit's index (all but '@' and '>').
bool advancesIndex(protocol::Op op);

} // namespace frezka::driver
