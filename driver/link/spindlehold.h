#pragma once
// SpindleHold: the spindle and the coolant across a hold, a stop and a tool lift (issue 14).
//
// Contract: stop() queues what switches the spindle off (!7V0, which also switches OUT0 off; on a
// GVE84 its relay on port 0) and every output the profile gives coolant, mist or air blow, and
// remembers what was on; nothing is sent for what is already off. restore(then) queues them back
// on as they were and, when the spindle was started again, waits the profile's spindle.spinUpMs
// before `then` — the motion back into the work (lowering Z, G); without a stop before, `then`
// runs at once; whenAtSpeed() waits for a spin-up under way. forget() drops what would be
// restored and the waits (the job ended: abort). The operator's word
// thus holds on the wire, and MachineState::outputsHeld tells the screen that the outputs are
// off for the hold and go on again first. The only fields are what stop() switched off.

#include "machine/unitprogram.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace frezka::driver {

class CoreHost;

class SpindleHold
{
public:
    explicit SpindleHold(CoreHost &host)
        : m_host(host)
    {}

    // Switches the spindle and coolant off (why: for messages, "pausing"). Idempotent.
    void stop(const char *why);
    // The job holds at M0/M1/M6: stop() when the profile says so (spindle.stopAt...).
    void atOperatorStop(machine::StopReason reason);
    // Back on as they were, the spin-up waited, then `then` (may be empty).
    void restore(std::function<void()> then);
    // `then` once a spindle that restore() started is at speed (at once when none is starting).
    void whenAtSpeed(std::function<void()> then);
    // Forget what was on: the job ended, nothing goes on again.
    void forget();
    // Whether stop() switched something off that restore() switches on again.
    bool stopped() const { return m_stopped; }
    // Seconds restore() will wait for the spindle (0 when it stays off).
    double spinUpS() const;

private:
    std::uint8_t coolantBits() const; // port-0 bits of coolant, mist and air blow (active low)
    std::uint8_t relayBit() const;    // GVE84: the bit that switches the spindle, else 0

    void atSpeed(); // the spin-up is over: the waiters go on

    CoreHost &m_host;
    bool m_stopped = false;
    bool m_starting = false;                        // restore() sent, its spin-up not yet over
    std::vector<std::function<void()>> m_waiters{}; // whenAtSpeed() meanwhile
    int m_permille = 0;         // the spindle's !7V before the stop (0: it was off)
    std::uint8_t m_port = 0xFF; // port 0 before the stop
};

} // namespace frezka::driver
