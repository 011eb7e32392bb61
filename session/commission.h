#pragma once
// The commissioning assistant's results (issue 21 item 1): the first connection to a real unit,
// step by step, each step with what it does, whether it moves anything, and its result.
//
// The steps that move nothing come first and run without an operator (UnitProbe): identify
// the unit and firmware, check the adopted readings of docs/gve-protocol.md that can be checked
// without motion, measure the link, read and decode the EEPROM. The steps that move or switch
// something (CommissionMoves) each run only after the operator confirmed it. Everything ends in
// a CommissionResult: an updated profile (written to a file the operator names) and a report
// (commissionreport.h). Plain values; the front ends word nothing of their own.

#include "machine/machineconfig.h"

#include <QString>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace frezka::session {

enum class StepResult : std::uint8_t {
    Held,       // checked, and it is as Frezka expects
    DidNotHold, // checked, and the unit does otherwise (details say how)
    NotChecked, // could not be checked (the unit lacks the feature, no reply ...)
    Skipped,    // the operator skipped it, or no operator was there to confirm it
};

// "held", "did not hold", "not checked", "skipped" in the user's language.
QString stepResultText(StepResult result);

// One step of the assistant as the operator sees it.
struct CommissionStep
{
    std::string id;             // stable: "identify", "readings", "link", "eeprom", "axis-x", ...
    QString title;              // translated: "Identify the unit"
    QString does;               // translated: what the step does
    bool moves = false;         // it moves an axis or switches an output
    bool needsOperator = false; // it asks the operator first (and waits for him)
    StepResult result = StepResult::NotChecked;
    QString details; // translated: what was seen
};

// One adopted reading (or protocol rule) checked against the unit.
struct ReadingCheck
{
    std::string section; // "§2.1"
    QString reading;     // translated: "A bad checksum is answered 4 ..."
    StepResult result = StepResult::NotChecked;
    QString details; // what was sent and what came back
};

// Round trips of one command class.
struct LinkClassFigure
{
    QString commandClass; // translated: "status (F)"
    std::string example;  // the command: "!0F"
    int samples = 0;
    int bytesPerExchange = 0; // sent + received
    double minMs = 0;
    double medianMs = 0;
    double maxMs = 0;
};

struct LinkFigures
{
    int baud = 0;
    std::vector<LinkClassFigure> classes;
    double bytesPerS = 0;         // over the packet exchanges, both ways
    double latencyOneWayMs = 0;   // estimated adapter latency, one way
    double proposedLatencyMs = 0; // for link.latencyMs
    double profileLatencyMs = 0;  // the profile's link.latencyMs before
};

// One EEPROM setting the profile keeps, read from the unit and decoded.
struct EepromRow
{
    machine::EepromEntry entry;      // address, kind, the profile's value, its name
    std::optional<double> unitValue; // nullopt when the unit did not answer
    std::string unitRaw;             // the reply line
    bool matches = false;
};

// The movement test of one axis.
struct AxisResult
{
    int axis = 0; // 0 X .. 3 A
    StepResult plus = StepResult::Skipped;
    StepResult minus = StepResult::Skipped;
    double movedMm = 0;               // asked per move (+ then −)
    std::optional<double> measuredMm; // what the operator measured for the + move
    double stepsPerMmBefore = 0;
    std::optional<double> stepsPerMmProposed;
    QString details;
};

struct CommissionResult
{
    std::string port;
    std::string variantId; // as identified ("gve64"), empty when unknown
    std::string firmware;  // reply to '?'
    std::string unitId;    // reply to 'Q'
    std::vector<CommissionStep> steps;
    std::vector<ReadingCheck> readings;
    LinkFigures link;
    std::vector<EepromRow> eeprom;
    std::vector<AxisResult> axes;
    machine::MachineConfig profileBefore;
    machine::MachineConfig profileAfter; // with the proposals applied (latency, steps/mm)
    std::string trace; // the serial trace of the session (docs/serial-trace.md text)

    CommissionStep *step(const std::string &id);
    const CommissionStep *step(const std::string &id) const;
};

// The assistant's steps in order, results NotChecked, for the profile (its axes, spindle,
// outputs, homing). The front ends list them; UnitProbe and CommissionMoves fill them in.
std::vector<CommissionStep> commissionSteps(const machine::MachineConfig &profile);
// A result to fill: the steps of the profile, the profile before and after (the same so far).
CommissionResult startCommission(const machine::MachineConfig &profile, const std::string &port);
// Marks every step that needs the operator as skipped, with `why` (no terminal, not confirmed).
void skipOperatorSteps(CommissionResult &result, const QString &why);

} // namespace frezka::session
