// The link's rules about the unit's command index. See linkrules.h.

#include "linkrules.h"

namespace frezka::driver {

using namespace frezka::protocol;

bool mustArriveOnce(Op op)
{
    switch (op) {
    case Op::Line:
    case Op::Vector:
    case Op::ExchangeUp:
    case Op::ExchangeDown:
    case Op::Keep:
    case Op::Restore:
    case Op::Go:
    case Op::Home:
    case Op::Jump:
    case Op::PacketStart:
    case Op::PacketEnd:
        return true;
    default:
        return false;
    }
}

int packetIndexAdvance(int commandCount)
{
    return commandCount + 2;
}

bool advancesIndex(Op op)
{
    return op != Op::Index && op != Op::Repeat;
}

} // namespace frezka::driver
