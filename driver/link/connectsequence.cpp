// ConnectSequence: the connect sequence (issue 5 item 3). See connectsequence.h.
//
//   %+        checksums on (sent plain; a unit that already has them on answers 4 with a
//             checksum, then it is sent again with one)
//   ? Q       identify: firmware string -> variant, compared with the profile; unit id
//   Y-        MPG off where the unit has one (reset state Y& refuses vectors); not when the
//             unit homes from an input (InputHoming parks it in Y& once idle)
//   T VN/VK   pause between moves, speed mode set explicitly (adopted reading §4)
//   SW0..SW3  interrupt masks and polarities from the profile
//   E*R       the unit's EEPROM compared with the profile; differences reported, never written
//   P4/PF F   position and status -> Idle (or, with a job kept over a link loss, re-establish
//             its progress from the counters -> Paused)

#include "connectsequence.h"

#include "driver/link/corehost.h"
#include "driver/link/eepromsync.h"
#include "driver/link/inputhoming.h"
#include "driver/link/job.h"
#include "machine/unitwire.h"

#include <algorithm>

namespace frezka::driver {

using namespace frezka::protocol;

MachineState &ConnectSequence::state()
{
    return m_host.liveState();
}

void ConnectSequence::start()
{
    // A new link may lead to a new unit, or to one that was switched off meanwhile: its
    // counters say nothing about where the axes are until they are homed again.
    state().homed = false;
    state().homedAxes = 0;
    m_host.markDirty();
    m_host.link().setChecksums(false);
    switchChecksums(1);
}

// %+ / %- first, framed plainly. A code 4 may mean the unit's checksums were on (it refused the
// plain command): send it framed. Any other refusal may be a byte damaged on the way (a damaged
// '%+' is an unknown command, 3): %+ and %- are harmless to repeat, so try again a few times.
void ConnectSequence::switchChecksums(int attempt)
{
    constexpr int kAttempts = 4;
    const Command first = m_host.options().checksums ? cmd::checksumOn() : cmd::checksumOff();
    // Ahead of any other step (an empty queue: the first).
    m_host.sendFront(first, [this, attempt](const Outcome &o) {
        const bool refused = o.status == OutcomeStatus::Ok && !o.reply.ok();
        if (refused && attempt < kAttempts) {
            m_host.log("switching checksums answered '" + o.raw + "': trying again");
            if (o.reply.code == ReplyCode::Syntax)
                m_host.link().setChecksums(!m_host.link().checksums());
            switchChecksums(attempt + 1);
            return;
        }
        if (!m_host.unitError(o, "switching checksums", MachineMode::Alarm))
            setupUnit();
    });
}

void ConnectSequence::setupUnit()
{
    const VariantInfo &want = variantInfo(m_host.config().unit.variant);
    m_host.send(cmd::version(), [this, &want](const Outcome &o) {
        if (m_host.unitError(o, "identifying the unit ('?')", MachineMode::Alarm))
            return;
        state().firmware = o.reply.values.empty() ? "" : o.reply.values[0];
        const auto found = variantFromFirmware(state().firmware);
        const auto wantFamily =
            want.variant == Variant::Gve64Phantom ? Variant::Gve64 : want.variant;
        if (!found || *found != wantFamily) {
            m_host.clearSteps();
            m_host.fail(
                {DriverCode::WrongVariant, {state().firmware, std::string(want.displayName)}}, &o,
                MachineMode::Alarm);
            return;
        }
        state().variant = want.variant;
        const auto version = firmwareVersion(state().firmware);
        state().firmwareVersion = version.value_or(0);
        state().features = featuresOf(want.variant, version);
        // The plan was made for the profile's firmware: a unit that knows less must be said.
        const Features promised = featuresOf(want.variant, m_host.config().unit.firmwareVersion);
        const Features &have = state().features;
        if ((promised.mpg && !have.mpg) || (promised.eepromFloat && !have.eepromFloat) ||
            (promised.vlVkXmNa && !have.vlVkXmNa)) {
            m_host.fail({DriverCode::FirmwareTooOld,
                         {std::to_string(state().firmwareVersion),
                          std::to_string(m_host.config().unit.firmwareVersion)}},
                        &o, MachineMode::Alarm);
        }
        m_host.markDirty();
        setupAfterIdentify();
    });
    m_host.send(cmd::identify(), [this](const Outcome &o) {
        if (m_host.unitError(o, "identifying the unit ('Q')", MachineMode::Alarm))
            return;
        state().unitId = o.reply.values.empty() ? "" : o.reply.values[0];
    });
}

// The rest of the connect sequence, for what the unit's firmware understands.
void ConnectSequence::setupAfterIdentify()
{
    auto check = [this](const char *what) {
        return [this, what](const Outcome &o) { m_host.unitError(o, what, MachineMode::Alarm); };
    };
    // MPG off, unless the unit is to home from its input: then the core parks it in Y& as
    // soon as it is idle (InputHoming), since Y- would disable that.
    if (state().features.mpg && !InputHoming::wanted(m_host.config(), state().features)) {
        m_host.send(cmd::mpgOff(), check("switching the MPG off"));
        state().mpgOn = false;
    }
    m_host.send(cmd::pause(std::clamp(m_host.config().motion.pauseMs, 1, 24)), check("setting T"));
    if (state().features.vlVkXmNa) {
        m_host.send(cmd::speedModeVn(), check("setting VN"));
        // VL from the profile's axis maxima: the feed override (XM) is capped per axis by them.
        const auto vl = machine::axisSpeedLimits(m_host.config());
        m_host.send(state().axisCount == 4 ? cmd::velocityLimit(vl[0], vl[1], vl[2], vl[3])
                                           : cmd::velocityLimit(vl[0], vl[1], vl[2]),
                    check("setting the axis speed limits (VL)"));
        // The override the window shows, also on a unit that kept another one or was reset.
        const int xm = m_job.feedOverride().toSend(state().overridePercent, m_job.active());
        m_host.send(cmd::multiplier(xm), check("setting the override (XM)"));
        state().overrideSentPercent = xm;
    } else {
        state().overridePercent = 100; // XU/XD changed queues that are gone now
        m_job.feedOverride().setSpeedScale(1.0);
    }
    const machine::EepromConfig &ee = m_host.config().eeprom;
    m_host.send(cmd::statusWrite(0, ee.interruptEnable), check("setting the interrupt mask"));
    m_host.send(cmd::statusWrite(2, ee.polarity), check("setting the input polarity"));
    if (m_host.config().unit.variant != Variant::Gve84) {
        m_host.send(cmd::statusWrite(1, ee.interruptEnableHigh),
                    check("setting the interrupt mask"));
        m_host.send(cmd::statusWrite(3, ee.polarityHigh), check("setting the input polarity"));
    }
    if (m_host.options().compareEeprom && ee.sync)
        m_eeprom.compare();
    probeDoublePacketStart();
    finish();
}

// A one-command packet opened with *S twice: "0,1" means the unit restarts an open packet on a
// second *S, and every packet is sent that way (see LinkOptions::doublePacketStart). Any other
// reply may be a byte damaged on the way (code 4 for a bad checksum looks like a refusal): the
// test is repeated, and only three refusals in a row switch the second *S off.
void ConnectSequence::probeDoublePacketStart()
{
    if (!m_host.options().packets || !m_host.options().link.doublePacketStart)
        return;
    m_host.send(cmd::flag(), [this](const Outcome &) { packetStartTest(1); });
}

void ConnectSequence::packetStartTest(int attempt)
{
    constexpr int kAttempts = 3;
    m_host.link().setDoublePacketStart(true);
    auto then = [this, attempt](const Outcome &o) {
        const bool ok = o.status == OutcomeStatus::Ok && o.reply.ok() && o.accepted == 1;
        // A damaged first *S leaves the index one short of where the packet leads, which the
        // engine cannot tell from a lost line: it fails the transaction but learns the index.
        // The test packet (one B) is harmless to repeat.
        if (o.status != OutcomeStatus::Ok && (attempt >= kAttempts || !m_host.link().unitIndex())) {
            m_host.link().setDoublePacketStart(false);
            m_host.unitError(o, "testing packets", MachineMode::Alarm);
            return;
        }
        if (!ok && attempt < kAttempts) {
            m_host.log("packet test answered '" + o.raw + "': testing again");
            packetStartTest(attempt + 1);
            return;
        }
        m_host.link().setDoublePacketStart(ok);
        m_host.log(ok ? "packets open with *S *S"
                      : "the unit refuses *S *S: packets open with one *S");
    };
    const int b = std::min(variantInfo(m_host.config().unit.variant).resetBrakeSpeed,
                           m_host.config().unit.maxPulseRate);
    m_host.startPacket({cmd::brake(b)}, std::move(then));
}

void ConnectSequence::finish()
{
    m_host.readPositionAndStatus([this] {
        if (state().mode != MachineMode::Connecting)
            return; // an error on the way
        if (m_job.resumeAfterReconnect())
            return;
        m_host.setMode(MachineMode::Idle);
    });
}

} // namespace frezka::driver
