#pragma once
// The commissioning's steps that move or switch something (issue 21 item 1), each only after
// the operator confirmed it, through the driver (a LinkWorker in the caller's thread, so every
// move goes through the link engine, the soft limits and the machine core like any jog):
// per axis a small slow move in + and back in − (the operator confirms the direction and
// enters the distance he measured: corrected steps per mm), the home and limit switches and
// the STOP button (the operator presses, the step watches the input), the spindle at two
// speeds, the outputs the profile uses, homing last. Every step can be skipped.

#include "driver/link/linkworker.h"
#include "session/commission.h"

#include <QString>

#include <optional>

namespace frezka::session {

// The operator at the machine: the CLI asks on the terminal, the GUI with buttons, tests by
// script. Each call returns when he answered.
class CommissionOperator
{
public:
    virtual ~CommissionOperator() = default;
    // The step is about to run: true = run it, false = skip it.
    virtual bool confirm(const CommissionStep &step) = 0;
    // A yes/no question ("Did X move 5 mm in +?").
    virtual bool ask(const QString &question) = 0;
    // A number (the measured distance); nullopt = no answer (keep the profile's value).
    virtual std::optional<double> askNumber(const QString &question) = 0;
    // Something to do now ("Press the X home switch"); the step then watches for it.
    virtual void instruct(const QString &text) = 0;
};

struct MoveOptions
{
    double axisMoveMm = 5;       // each way
    double watchSwitchS = 20;    // how long a switch test waits for the input
    double homingTimeoutS = 300; // how long homing may take
    // For tests: the transports of the driver (the default opens the serial port).
    driver::LinkWorker::TransportFactory factory;
};

// Connects the driver to `port` at `baud` and runs every step of `result` that needs the
// operator, in order, filling the steps and result.axes; proposals go to result.profileAfter.
void runOperatorSteps(const QString &port, int baud, CommissionResult &result,
                      CommissionOperator &op, const MoveOptions &options = {});

} // namespace frezka::session
