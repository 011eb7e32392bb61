// MachineCore: the connect sequence (issue 5 item 3).
//
//   %+        checksums on (sent plain; a unit that already has them on answers 4 with a
//             checksum, then it is sent again with one)
//   ? Q       identify: firmware string -> variant, compared with the profile; unit id
//   Y-        MPG off where the unit has one (reset state Y& refuses vectors)
//   T VN/VK   pause between moves, speed mode set explicitly (adopted reading §4)
//   SW0..SW3  interrupt masks and polarities from the profile
//   E*R       the unit's EEPROM compared with the profile; differences reported, never written
//   P4/PF F   position and status -> Idle (or, with a job kept over a link loss, re-establish
//             its progress from the counters -> Paused)

#include "machinecore.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;

void MachineCore::connectSequence()
{
    m_engine.setChecksums(false);
    switchChecksums(1);
}

// %+ / %- first, framed plainly. A code 4 may mean the unit's checksums were on (it refused the
// plain command): send it framed. Any other refusal may be a byte damaged on the way (a damaged
// '%+' is an unknown command, 3): %+ and %- are harmless to repeat, so try again a few times.
void MachineCore::switchChecksums(int attempt)
{
    constexpr int kAttempts = 4;
    const Command first = m_options.checksums ? cmd::checksumOn() : cmd::checksumOff();
    const auto front = [this, first](Then then) {
        if (m_steps.empty())
            send(first, std::move(then));
        else
            sendFront(first, std::move(then));
    };
    front([this, attempt](const Outcome &o) {
        const bool refused = o.status == OutcomeStatus::Ok && !o.reply.ok();
        if (refused && attempt < kAttempts) {
            log("switching checksums answered '" + o.raw + "': trying again");
            if (o.reply.code == ReplyCode::Syntax)
                m_engine.setChecksums(!m_engine.checksums());
            switchChecksums(attempt + 1);
            return;
        }
        if (!unitError(o, "switching checksums", MachineMode::Alarm))
            setupUnit();
    });
}

void MachineCore::setupUnit()
{
    const VariantInfo &want = variantInfo(m_config.unit.variant);
    send(cmd::version(), [this, &want](const Outcome &o) {
        if (unitError(o, "identifying the unit ('?')", MachineMode::Alarm))
            return;
        m_state.firmware = o.reply.values.empty() ? "" : o.reply.values[0];
        const auto found = variantFromFirmware(m_state.firmware);
        const auto wantFamily =
            want.variant == Variant::Gve64Phantom ? Variant::Gve64 : want.variant;
        if (!found || *found != wantFamily) {
            m_steps.clear();
            fail("the unit reports firmware '" + m_state.firmware +
                     "' but the machine profile is "
                     "for a " +
                     std::string(want.displayName) + "; choose the matching profile",
                 &o, MachineMode::Alarm);
            return;
        }
        m_state.variant = want.variant;
        const auto version = firmwareVersion(m_state.firmware);
        m_state.firmwareVersion = version.value_or(0);
        m_state.features = featuresOf(want.variant, version);
        // The plan was made for the profile's firmware: a unit that knows less must be said.
        const Features promised = featuresOf(want.variant, m_config.unit.firmwareVersion);
        const Features &have = m_state.features;
        if ((promised.mpg && !have.mpg) || (promised.eepromFloat && !have.eepromFloat) ||
            (promised.vlVkXmNa && !have.vlVkXmNa)) {
            fail("the unit reports firmware v" + std::to_string(m_state.firmwareVersion) +
                     " but the machine profile says v" +
                     std::to_string(m_config.unit.firmwareVersion) +
                     ", and plans for the profile's firmware may use what this one lacks (MPG "
                     "and EEPROM floats need v10; VK, VL, XM and setting one axis's counter "
                     "v19): set unit.firmwareVersion to " +
                     std::to_string(m_state.firmwareVersion) + " in the profile",
                 &o, MachineMode::Alarm);
        }
        m_dirty = true;
        setupAfterIdentify();
    });
    send(cmd::identify(), [this](const Outcome &o) {
        if (unitError(o, "identifying the unit ('Q')", MachineMode::Alarm))
            return;
        m_state.unitId = o.reply.values.empty() ? "" : o.reply.values[0];
    });
}

// The rest of the connect sequence, for what the unit's firmware understands.
void MachineCore::setupAfterIdentify()
{
    auto check = [this](const char *what) {
        return [this, what](const Outcome &o) { unitError(o, what, MachineMode::Alarm); };
    };
    if (m_state.features.mpg) {
        send(cmd::mpgOff(), check("switching the MPG off"));
        m_state.mpgOn = false;
    }
    send(cmd::pause(std::clamp(m_config.motion.pauseMs, 1, 24)), check("setting T"));
    if (m_state.features.vlVkXmNa)
        send(cmd::speedModeVn(), check("setting VN"));
    const machine::EepromConfig &ee = m_config.eeprom;
    send(cmd::statusWrite(0, ee.interruptEnable), check("setting the interrupt mask"));
    send(cmd::statusWrite(2, ee.polarity), check("setting the input polarity"));
    if (m_config.unit.variant != Variant::Gve84) {
        send(cmd::statusWrite(1, ee.interruptEnableHigh), check("setting the interrupt mask"));
        send(cmd::statusWrite(3, ee.polarityHigh), check("setting the input polarity"));
    }
    if (m_options.compareEeprom && ee.sync)
        compareEeprom();
    probeDoublePacketStart();
    connected();
}

// A one-command packet opened with *S twice: "0,1" means the unit restarts an open packet on a
// second *S, and every packet is sent that way (see LinkOptions::doublePacketStart). Any other
// reply may be a byte damaged on the way (code 4 for a bad checksum looks like a refusal): the
// test is repeated, and only three refusals in a row switch the second *S off.
void MachineCore::probeDoublePacketStart()
{
    if (!m_options.packets || !m_options.link.doublePacketStart)
        return;
    m_steps.push_back({cmd::flag(), [this](const Outcome &) { packetStartTest(1); }});
}

void MachineCore::packetStartTest(int attempt)
{
    constexpr int kAttempts = 3;
    m_engine.setDoublePacketStart(true);
    m_inFlight = [this, attempt](const Outcome &o) {
        const bool ok = o.status == OutcomeStatus::Ok && o.reply.ok() && o.accepted == 1;
        // A damaged first *S leaves the index one short of where the packet leads, which the
        // engine cannot tell from a lost line: it fails the transaction but learns the index.
        // The test packet (one B) is harmless to repeat.
        if (o.status != OutcomeStatus::Ok && (attempt >= kAttempts || !m_engine.unitIndex())) {
            m_engine.setDoublePacketStart(false);
            unitError(o, "testing packets", MachineMode::Alarm);
            return;
        }
        if (!ok && attempt < kAttempts) {
            log("packet test answered '" + o.raw + "': testing again");
            packetStartTest(attempt + 1);
            return;
        }
        m_engine.setDoublePacketStart(ok);
        log(ok ? "packets open with *S *S" : "the unit refuses *S *S: packets open with one *S");
    };
    const int b =
        std::min(variantInfo(m_config.unit.variant).resetBrakeSpeed, m_config.unit.maxPulseRate);
    m_engine.startPacket({cmd::brake(b)}, m_now);
}

void MachineCore::compareEeprom()
{
    m_state.eepromDifferences.clear();
    const bool wide = m_state.features.eepromFloat;
    for (const machine::EepromEntry &e : machine::eepromEntries(m_config)) {
        Command c;
        switch (e.kind) {
        case machine::EepromKind::Byte:
            c = cmd::eepromReadByte(e.address);
            break;
        case machine::EepromKind::Float:
            c = cmd::eepromReadFloat(e.address);
            break;
        case machine::EepromKind::Uint32:
            c = cmd::eepromReadUint(e.address);
            break;
        }
        if (!wide && e.kind != machine::EepromKind::Byte)
            continue;
        send(c, [this, e](const Outcome &o) {
            if (unitError(o, "reading the EEPROM", MachineMode::Alarm))
                return;
            double have = 0;
            if (e.kind == machine::EepromKind::Byte)
                have = o.reply.hexValue().value_or(0);
            else
                have = o.reply.real().value_or(0);
            const double tolerance = e.kind == machine::EepromKind::Float
                                         ? 1e-4 * std::max(1.0, std::abs(e.value))
                                         : 0.0;
            if (std::abs(have - e.value) > tolerance) {
                const std::string text = e.what + ": unit " + o.reply.values.front() +
                                         ", profile " + std::to_string(e.value);
                m_state.eepromDifferences.push_back(text);
                m_dirty = true;
                log("EEPROM differs: " + text);
            }
        });
    }
}

void MachineCore::connected()
{
    readPositionAndStatus([this] {
        if (m_state.mode != MachineMode::Connecting)
            return; // an error on the way
        if (m_job.resumeAfterReconnect())
            return;
        setMode(MachineMode::Idle);
    });
}

void MachineCore::readPositionAndStatus(std::function<void()> then)
{
    send(positionCommand(), [this](const Outcome &o) {
        if (unitError(o, "reading the position", MachineMode::Alarm))
            return;
        applyPosition(o.reply);
    });
    send(cmd::flag(), [this, then = std::move(then)](const Outcome &o) {
        if (unitError(o, "reading the status", MachineMode::Alarm))
            return;
        m_state.flags = *o.reply.hexValue();
        m_state.run = (m_state.flags & 0x40) != 0;
        m_state.inta = (m_state.flags & 0x80) != 0;
        m_state.queueFull = (m_state.flags & 0x20) != 0;
        m_lastPoll = m_now;
        if (then)
            then();
    });
}

} // namespace frezka::driver

namespace frezka::driver {

MachineCore::Result MachineCore::writeEeprom(double now)
{
    if (m_state.mode != MachineMode::Idle)
        return MachineError{std::string("Writing the EEPROM is not possible now (the machine is ") +
                                machineModeName(m_state.mode) + ")",
                            {},
                            {},
                            -1};
    const bool wide = m_state.features.eepromFloat;
    for (const machine::EepromEntry &e : machine::eepromEntries(m_config)) {
        Command c;
        switch (e.kind) {
        case machine::EepromKind::Byte:
            c = cmd::eepromWriteByte(e.address, static_cast<int>(std::lround(e.value)));
            break;
        case machine::EepromKind::Float:
            c = cmd::eepromWriteFloat(e.address, e.value);
            break;
        case machine::EepromKind::Uint32:
            c = cmd::eepromWriteUint(e.address, std::llround(e.value));
            break;
        }
        if (!wide && e.kind != machine::EepromKind::Byte)
            continue;
        send(c, [this, what = e.what](const Outcome &o) {
            unitError(o, "writing the EEPROM (" + what + ")", MachineMode::Alarm);
        });
    }
    compareEeprom();
    pump(now);
    return std::nullopt;
}

} // namespace frezka::driver
