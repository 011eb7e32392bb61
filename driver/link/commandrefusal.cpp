// The protocol's problems as driver messages. See commandrefusal.h.

#include "commandrefusal.h"

#include <string>

namespace frezka::driver {

using protocol::CommandProblem;
using protocol::ParseProblem;

DriverMessage commandCheckMessage(const protocol::CommandCheck &k)
{
    const std::string &at = k.command;
    switch (k.problem) {
    case CommandProblem::None:
        return {};
    case CommandProblem::AddressRange:
        return {DriverCode::CommandAddressRange, {at}};
    case CommandProblem::NoSpindleAddress:
        return {DriverCode::CommandNoSpindleAddress, {at, k.unit}};
    case CommandProblem::NotOnAddress7:
        return {DriverCode::CommandNotOnAddress7, {at}};
    case CommandProblem::SpindleOnAddress7:
        return {DriverCode::CommandSpindleOnAddress7, {at}};
    case CommandProblem::AddressZeroOnly:
        return {DriverCode::CommandAddressZeroOnly, {at, k.unit}};
    case CommandProblem::ComponentCount:
        return {k.high == 4 ? DriverCode::CommandComponents34 : DriverCode::CommandComponents3,
                {at, std::to_string(k.value), k.unit}};
    case CommandProblem::ValueOutOfRange:
        return {
            DriverCode::CommandOutOfRange,
            {at, k.what, std::to_string(k.value), std::to_string(k.low), std::to_string(k.high)}};
    case CommandProblem::NotFinite:
        return {DriverCode::CommandNotFinite, {at}};
    case CommandProblem::ZeroTravel:
        return {DriverCode::CommandZeroTravel, {at}};
    case CommandProblem::NoSuchAxis:
        return {DriverCode::CommandNoSuchAxis, {at, k.unit, k.what}};
    case CommandProblem::NoSuchCommand:
        return {DriverCode::CommandNoSuchCommand, {at, k.unit, k.what}};
    case CommandProblem::NotInPacket:
        return {DriverCode::CommandNotInPacket, {at}};
    case CommandProblem::EmptyPacket:
        return {DriverCode::CommandEmptyPacket};
    }
    return {};
}

DriverMessage parseProblemMessage(const protocol::ParsedCommand &p)
{
    if (p.status == protocol::ParseStatus::Ok)
        return {};
    const std::string &at = p.line;
    switch (p.problem) {
    case ParseProblem::None:
        return {};
    case ParseProblem::NoAddress:
        return {DriverCode::LineNoAddress, {at}};
    case ParseProblem::BadChecksum:
        return {DriverCode::LineBadChecksum, {at}};
    case ParseProblem::UnknownCommand:
        return {DriverCode::LineUnknownCommand, {at}};
    case ParseProblem::MissingNumber:
        return {DriverCode::LineMissingNumber, {at}};
    case ParseProblem::NumberTooLarge:
        return {DriverCode::LineNumberTooLarge, {at, p.field}};
    case ParseProblem::NotDecimal:
        return {DriverCode::LineNotDecimal, {at, p.field}};
    case ParseProblem::NotHexByte:
        return {DriverCode::LineNotHexByte, {at, p.field}};
    case ParseProblem::NotANumber:
        return {DriverCode::LineNotANumber, {at, p.field}};
    case ParseProblem::ParameterCount:
        return {DriverCode::LineParameterCount, {at}};
    case ParseProblem::HomeNeedsAxis:
        return {DriverCode::LineHomeNeedsAxis, {at}};
    case ParseProblem::OutputNeedsByte:
        return {DriverCode::LineOutputNeedsByte, {at}};
    case ParseProblem::UnexpectedParameters:
        return {DriverCode::LineUnexpectedParameters, {at}};
    }
    return {};
}

} // namespace frezka::driver
