#pragma once
// InputHoming: keeps homing from the unit's input (EEPROM 0x07) working while Frezka is
// connected, with the MPG sequences of the GVE64/GVE114 manuals.
//
// Contract: the unit starts homing from an input (held > 1 s, the axis chosen on the MPG's axis
// switch) only while its MPG is on without reports (Y&, the state after reset): Y- and Y+
// disable it (GVE64 manual 12.3 and 13.5.8, docs/gve-protocol.md §6, §13). But with the MPG on
// the unit counts as running and refuses vectors. So when the profile names a homing input
// (eeprom.homingInput 3..7, the MPG on in eeprom.mpg) and the unit has an MPG, the machine
// stands parked in Y& whenever it is idle (park(), at every return to Idle, the connect
// sequence included, which therefore sends no Y-), and each operation that moves it (a job, a
// jog, homing by W) is preceded by Y- (unpark(), before that operation's own commands). Where
// the profile names no homing input nothing changes: the connect sequence's Y- stays, and
// these send nothing. The unit's input homing is its own: Frezka follows the position in its
// polls but cannot know which axis was chosen nor what the unit set its counter to, so the
// axis does not count as homed for the soft limits.

#include "machine/machineconfig.h"
#include "protocol/command.h"
#include "protocol/variant.h"

#include <functional>

namespace frezka::driver {

class CoreHost;

class InputHoming
{
public:
    explicit InputHoming(CoreHost &host)
        : m_host(host)
    {}

    // The profile asks for homing from an input and the connected unit has an MPG.
    bool wanted() const;
    static bool wanted(const machine::MachineConfig &config, const protocol::Features &unit);
    // A new link: the unit's MPG state is unknown until the next park().
    void linkOpened() { m_parked = false; }
    // Idle again: Y& (MPG on, silent) so that the input can start homing. Queued last.
    void park();
    // Before a motion, ahead of its commands: Y- (after a Y& still queued). True when it was
    // sent (a refused operation then parks again).
    bool unpark();

private:
    CoreHost &m_host;
    bool m_parked = false;
};

} // namespace frezka::driver
