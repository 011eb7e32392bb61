#pragma once
// CoreHost: what an activity of MachineCore (the job, its path guard, tool lift, ...) may use of
// the core. The core owns the wire and its order (operation steps before polls before the job's
// stream), the published MachineState, the status waits and the error reporting; an activity
// owns only its own fields and decides its own next step, then asks the host to put it on the
// wire. Every continuation runs in the core's one thread, at the reply (or the settled failure)
// of its command. MachineCore implements this; nobody else needs to.

#include "driver/link/linkengine.h"
#include "driver/link/machinestate.h"
#include "machine/machineconfig.h"
#include "machine/unitprogram.h"

#include <functional>
#include <string>
#include <vector>

namespace frezka::driver {

struct CoreOptions;

class CoreHost
{
public:
    using Then = std::function<void(const Outcome &)>;

    // ---- the wire: steps run in order before any poll or job command
    virtual void send(const protocol::Command &c, Then then) = 0;
    virtual void sendFront(const protocol::Command &c, Then then) = 0;
    virtual void clearSteps() = 0;
    // Starts a transaction at once (the link is idle: the job's own stream).
    virtual void start(const protocol::Command &c, Then then) = 0;
    virtual void startPacket(std::vector<protocol::Command> packet, Then then) = 0;

    // ---- waits on the unit's status (F is read to find out)
    virtual void afterIdle(std::function<void()> then) = 0;    // RUN = 0
    virtual void afterJobIdle(std::function<void()> then) = 0; // the same, only while running
    virtual void clearJobIdleWaiters() = 0;
    // The job waits for the unit to stand while it runs (afterJobIdle pending): the poller reads
    // F alone, back to back, so that the stop is seen one F exchange after it (poller.h).
    virtual bool waitingForJobStand() const = 0;
    virtual void dropPending() = 0; // the queued steps and every wait for idle
    virtual void afterStopOrInterrupt(std::function<void()> then) = 0; // RUN = 0 or INTA = 1
    virtual void whenStill(std::function<void()> then) = 0;            // two equal position reads
    // Runs `then` once `seconds` have passed (the spindle's spin-up); dropPending() cancels it.
    virtual void afterDelay(double seconds, std::function<void()> then) = 0;

    // ---- state and errors
    virtual MachineState &liveState() = 0; // the state the core publishes
    virtual void markDirty() = 0;
    virtual void setMode(MachineMode mode) = 0;
    virtual void publish() = 0;
    // Reports an error (a code with its arguments, drivererror.h) and sets the mode.
    virtual void fail(const DriverMessage &message, const Outcome *o, MachineMode mode) = 0;
    // True (and the error reported, the mode set) when `o` is not an accepted reply.
    virtual bool unitError(const Outcome &o, const std::string &what, MachineMode mode) = 0;
    virtual void log(const std::string &text) = 0;
    virtual void jobFinished(bool ok) = 0;

    // ---- readings
    virtual void applyPosition(const protocol::Reply &r) = 0;
    virtual void applyFlags(std::uint8_t flags) = 0;
    virtual protocol::Command positionCommand() const = 0; // P4 or PF for the axis count
    // Queues the position and F reads (a fresh poll); `then` (may be empty) after F.
    virtual void readPositionAndStatus(std::function<void()> then) = 0;

    // ---- the unit's hold (INTA): whether resuming needs G; an expected interrupt (probe)
    virtual void setHoldNeedsGo(bool on) = 0;
    virtual void setHaltExpected(bool on) = 0;
    // The job holds at an operator stop (M0 / M1 / M6, machine::StopReason): the spindle and
    // coolant go off when the profile says so (SpindleHold).
    virtual void heldAtOperatorStop(machine::StopReason reason) = 0;

    // ---- context
    virtual double now() const = 0;
    virtual double rttS() const = 0; // a poll's round trip, smoothed
    virtual void restartPollCount() = 0;
    // The position and F were just read (the job found the unit standing where the plan has
    // it): the poll schedule starts again now, and no poll comes between that and the restart.
    virtual void restartPolls() = 0;
    virtual const machine::MachineConfig &config() const = 0;
    virtual const CoreOptions &options() const = 0;
    virtual LinkEngine &link() = 0;

protected:
    ~CoreHost() = default;
};

} // namespace frezka::driver
