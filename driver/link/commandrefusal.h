#pragma once
// Why the protocol refuses a command or a line, as a driver message: the protocol's check
// (protocol::CommandCheck, validate()) and parse (protocol::ParsedCommand) carry what is wrong
// as a problem with its values; these turn it into a 5xx DriverCode with those values as
// arguments, so that a refusal (InvalidCommand, OverrideInvalid, NotACommand, SpeedInvalid,
// HomingInvalid) carries it as its detail and the front ends word all of it in the user's
// language. englishText() of the result is the protocol's English message.

#include "driver/link/drivererror.h"

#include "protocol/command.h"
#include "protocol/commandparser.h"

namespace frezka::driver {

// A failed check (check.error != None) as a message; empty for a check that passed.
DriverMessage commandCheckMessage(const protocol::CommandCheck &check);
// A line parseCommand() did not accept (status != Ok) as a message; empty for a parsed one.
DriverMessage parseProblemMessage(const protocol::ParsedCommand &parsed);

} // namespace frezka::driver
