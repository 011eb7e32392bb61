// Unit: framing (lines, checksums, packets, watchdog, deferred replies), the clock, inputs and
// interrupts, homing progress. The command set itself is in unit_commands.cpp.

#include "driver/emulator/unit_impl.h"

#include "protocol/checksum.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace frezka::emulator {

Unit::Impl::Impl(UnitOptions opts)
    : options(std::move(opts))
    , info(&protocol::variantInfo(options.variant))
    , firmware(options.firmware.empty() ? std::string(info->firmware) : options.firmware)
    , features(protocol::featuresOf(options.variant, protocol::firmwareVersion(firmware)))
    , maxRate(options.maxPulseRate > 0 ? options.maxPulseRate : info->defaultMaxPulseRate)
    , eeprom(options.variant)
    , switches(options.switches)
{
    engine.onStopped = [this] { onStopped(); };
    engine.setTraceEnabled(options.trace);
    safety.setModel(options.machine);
    engine.setAxisMax(options.machine.axisMaxPulsesPerS);
    engine.onVectorStart = [this](const MotionVector &v) {
        if (!v.isHoming) {
            const bool probing = (interruptMask(false) >> options.surface.input) & 1;
            safety.vectorStarts(engine.position(), engine.headEnd(), engine.now(), probing);
        }
    };
    for (const EepromPreset &p : options.eepromPreset) {
        switch (p.kind) {
        case EepromPreset::Kind::Byte:
            eeprom.setByte(p.address, static_cast<std::uint8_t>(p.value));
            break;
        case EepromPreset::Kind::Float:
            eeprom.writeFloat(p.address, static_cast<float>(p.value));
            break;
        case EepromPreset::Kind::Uint32:
            eeprom.writeUint32(p.address, static_cast<std::uint32_t>(p.value));
            break;
        }
    }
    if (!options.eepromFile.empty()) {
        const std::string err = eeprom.load(options.eepromFile);
        // A missing file starts from the factory contents and is created on the first write.
        if (!err.empty() && !err.starts_with("cannot open"))
            eepromError = err;
    }
    cfg = decodeSettings(eeprom, options.variant, maxRate);
    for (int i = 0; i < 4; ++i) // the machine was wired so that its axes run with the counters
        wiring[i] = cfg.dirReversed[i] ? -1 : 1;
    resetState(true);
}

// docs/gve-protocol.md §3: the state after power-on or J.
void Unit::Impl::resetState(bool powerOn)
{
    engine.reset();
    limits = SpeedLimits{};
    limits.maxPulseRate = maxRate;
    engine.setLimits(limits);
    accelK = 20;
    speed = 1000;
    brake = info->resetBrakeSpeed;
    shortSteps = 512;
    pauseMs = readings::kResetPauseMs;
    engine.setPauseS(pauseMs / 1000.0);
    velocityCorrection = readings::kResetModeIsVk;
    std::fill(std::begin(st), std::end(st), 0);
    inta = intcom = stopBit = freeBit = false;
    mpg = features.mpg ? Mpg::Silent : Mpg::Off;
    outputs = 0xFF;
    spindle = 0;
    noteSpindle();
    kept = false;
    keptQueue = {};
    homing.reset();
    deferred = Deferred::None;
    checksums = false;
    index = 0;
    lastReply.clear();
    packetOpen = false;
    packet.clear();
    rx = Rx::Idle;
    line.clear();
    backlog.clear();
    if (powerOn)
        deafUntil = -1;
    wheel.moving = false;
    homingInputSince = -1;
    latchPowerOn();
    updateWatches();
    checkInterrupts(); // takes the current input state as the reference, nothing is enabled
}

// ---- framing -------------------------------------------------------------------------------

void Unit::Impl::feed(char c)
{
    switch (rx) {
    case Rx::AfterCr:
        rx = Rx::Idle;
        if (c == '\n' && readings::kIgnoreLfAfterCr)
            return;
        [[fallthrough]];
    case Rx::Idle:
        if (c == '!') {
            rx = Rx::InLine;
            line.clear();
            lineOverlong = false;
            lineStart = engine.now();
        } else {
            ++stats.discardedBytes;
        }
        return;
    case Rx::InLine:
        if (c == '\r') {
            rx = Rx::AfterCr;
            lineComplete();
        } else if (c == '!') { // a new command cuts off an incomplete one
            stats.discardedBytes += static_cast<std::int64_t>(line.size()) + 1;
            line.clear();
            lineOverlong = false;
            lineStart = engine.now();
        } else if (line.size() >= readings::kMaxLineLength) {
            lineOverlong = true;
        } else {
            line += c;
        }
        return;
    }
}

void Unit::Impl::lineComplete()
{
    if (line.empty() || line[0] < '0' || line[0] > '7') {
        stats.discardedBytes += static_cast<std::int64_t>(line.size()) + 2;
        return;
    }
    const int address = line[0] - '0';
    if (address != options.address && !(address == 7 && answersSpindle()))
        return; // another unit on the line answers this one
    ++stats.commands;
    if (lineOverlong) {
        if (packetOpen)
            packet.push_back({{}, 4});
        else
            sendReply({4, {}});
        return;
    }
    std::string_view body(line);
    body.remove_prefix(1);
    if (checksums) {
        const auto comma = body.rfind(',');
        const auto given = comma == std::string_view::npos
                               ? std::nullopt
                               : protocol::parseHexByte(body.substr(comma + 1));
        const std::string summed = "!" + line.substr(0, comma + 2);
        if (!given || protocol::checksum(summed) != *given) {
            ++stats.checksumErrors;
            const int code =
                options.badChecksumCode >= 0 ? options.badChecksumCode : readings::kBadChecksumCode;
            if (packetOpen)
                packet.push_back({{}, code});
            else
                sendReply({code, {}});
            return; // readings::kBadChecksumAdvancesIndex == false
        }
        body = body.substr(0, comma);
    }
    handleLine(address, body);
}

void Unit::Impl::handleLine(int address, std::string_view body)
{
    if (readings::advancesIndex(body))
        index = (index + 1) % 256;
    if (packetOpen) {
        if (body == "*S") {
            packet.clear();
            packetLastLine = engine.now();
            return;
        }
        if (body.starts_with("*E")) {
            packetOpen = false;
            int declared = -1;
            std::string_view n = body.substr(2);
            const auto digit = [](char c) { return c >= '0' && c <= '9'; };
            if (!n.empty() && n.size() <= 4 && std::all_of(n.begin(), n.end(), digit))
                declared = std::stoi(std::string(n));
            const Reply r = executePacket(declared);
            packet.clear();
            sendReply(r);
            lastReply = formatReply(r);
            return;
        }
        if (readings::advancesIndex(body)) {
            packet.push_back({std::string(body), 0});
            packetLastLine = engine.now();
            return;
        }
        packetOpen = false; // '@' or '>' ends an unfinished packet: nothing of it runs
        packet.clear();
    }
    observeSafety();
    const Reply r = execute(address, body);
    observeSafety();
    if (r.code < 0)
        return; // deferred (H, W) or no reply at all (*S)
    sendReply(r);
    if (readings::advancesIndex(body) && !body.starts_with("J"))
        lastReply = formatReply(r);
}

std::string Unit::Impl::formatReply(const Reply &r) const
{
    std::string text(1, "0123456789ABCDEF"[(r.code & 7) | (inta ? 8 : 0)]);
    if (!r.values.empty())
        text += "," + r.values;
    if (checksums) {
        text += ',';
        text += protocol::hexByte(protocol::checksum(text));
    }
    text += '\r';
    return text;
}

void Unit::Impl::sendReply(const Reply &r)
{
    tx += formatReply(r);
}

double Unit::Impl::watchdogAt() const
{
    if (rx == Rx::InLine && !line.empty()) {
        const int address = line[0] - '0';
        if (address == options.address || (address == 7 && answersSpindle()))
            return lineStart + readings::kWatchdogSeconds;
        return kNever;
    }
    if (packetOpen)
        return packetLastLine + readings::kWatchdogSeconds;
    return kNever;
}

void Unit::Impl::fireWatchdog()
{
    ++stats.watchdogs;
    if (rx == Rx::InLine) {
        stats.discardedBytes += static_cast<std::int64_t>(line.size()) + 1;
        rx = Rx::Idle;
        line.clear();
    }
    packetOpen = false;
    packet.clear();
    sendReply({2, {}});
}

void Unit::Impl::processBacklog()
{
    while (!backlog.empty() && deferred == Deferred::None && deafUntil <= engine.now()) {
        const char c = backlog.front();
        backlog.erase(0, 1);
        feed(c);
    }
}

// ---- clock -----------------------------------------------------------------------------------

namespace {

// Rounding of the clock: a few ulps of the time t (never less than those of one second).
double clockSlack(double t)
{
    return 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t));
}

} // namespace

double Unit::Impl::nextEventIn() const
{
    const double now = engine.now();
    double next = engine.nextEventIn();
    if (deferred == Deferred::None)
        next = std::min(next, std::max(0.0, watchdogAt() - now));
    if (deafUntil > now)
        next = std::min(next, deafUntil - now);
    next = std::min(next, std::max(0.0, wheelEventAt() - now));
    return next;
}

void Unit::Impl::advanceBy(double seconds)
{
    // What is left is kept as a duration, never as a clock reading: (now + dt) - now is dt
    // rounded to the clock's ulp and can fall short of an event exactly dt ahead. An event
    // within a few ulps of the clock beyond what is left counts as reached, so that
    // advance(nextEventIn()) always takes its event, even hours into a job.
    double left = std::max(0.0, seconds);
    for (;;) {
        const double event = nextEventIn();
        const bool reached = event <= left + clockSlack(engine.now());
        const double dt = reached ? event : left;
        engine.step(dt);
        left = std::max(0.0, left - dt);
        if (options.surface.active())
            updateWatches(); // the surface under the new X/Y
        observeSafety();
        checkWheel();
        checkInterrupts();
        checkHoming();
        if (deferred == Deferred::None && watchdogAt() <= engine.now())
            fireWatchdog();
        if (deafUntil >= 0 && deafUntil <= engine.now()) {
            deafUntil = -1;
            processBacklog();
        }
        if (deferred == Deferred::None && !backlog.empty() && deafUntil < 0)
            processBacklog();
        if (!reached)
            return;
    }
}

// ---- inputs and interrupts ------------------------------------------------------------------

std::uint16_t Unit::Impl::inputLevels() const
{
    std::uint16_t levels = manualInputs;
    const auto motor = motorPosition(); // switches sit on the machine (EEPROM 0x05, 0x0C)
    const auto pos = engine.position();
    for (const PositionSwitch &s : switches) {
        const std::int64_t p = motor[s.axis];
        const bool on = s.side < 0 ? p <= s.positionSteps : p >= s.positionSteps;
        if (on)
            levels |= static_cast<std::uint16_t>(1u << s.input);
    }
    const ProbeSurface &surface = options.surface;
    if (surface.active()) {
        const bool touching = pos[2] <= surface.touchZSteps(pos[0], pos[1]);
        const auto bit = static_cast<std::uint16_t>(1u << surface.input);
        levels = touching == surface.contactHigh ? levels | bit : levels & ~bit;
    }
    return levels;
}

void Unit::Impl::updateWatches()
{
    std::vector<MotionEngine::Watch> watches;
    for (const PositionSwitch &s : switches) {
        // In counter coordinates: the motor runs against the counter when DIR is reversed,
        // and a slaved A runs with its master's counter.
        const int axis = s.axis == 3 && cfg.aSlavedTo >= 0 ? cfg.aSlavedTo : s.axis;
        const int sign = axisSign(axis);
        const std::int64_t at = sign * s.positionSteps;
        watches.push_back({axis, sign * s.side < 0 ? at + 1 : at});
    }
    if (options.surface.active()) { // aimed under the current X/Y (surface.h)
        const auto pos = engine.position();
        watches.push_back({2, options.surface.touchZSteps(pos[0], pos[1]) + 1});
        if (options.surface.kind == ProbeSurface::Kind::Block) { // its sides
            const auto sides = options.surface.sideThresholds();
            for (int i = 0; i < 4; ++i)
                watches.push_back({i / 2, sides[std::size_t(i)]});
        }
    }
    engine.setWatches(std::move(watches));
}

void Unit::Impl::checkInterrupts()
{
    const std::uint16_t levels = inputLevels();
    const std::uint16_t enabled = interruptMask(false);
    const std::uint16_t polarity = interruptMask(true);
    std::uint16_t active = 0;
    for (int i = 0; i < 16; ++i) {
        if (readings::inputActive((levels >> i) & 1, (polarity >> i) & 1))
            active |= static_cast<std::uint16_t>(1u << i);
    }
    std::uint16_t fired = active & ~prevActive & enabled;
    prevActive = active;
    checkInputHoming(active);
    if (homing)
        fired &= static_cast<std::uint16_t>(~(1u << homing->axis)); // its own switch
    if (!fired)
        return;
    ++stats.interrupts;
    st[4] |= static_cast<std::uint8_t>(fired & 0xFF);
    st[5] |= static_cast<std::uint8_t>(fired >> 8);
    inta = true;
    if (homing) {
        engine.clear();
        engine.requestStop();
        finishHoming(readings::kHomingNotFoundCode);
        return;
    }
    stopBit = engine.isMoving();
    engine.requestStop();
}

void Unit::Impl::onStopped()
{
    stopBit = false;
    if (wheel.moving) { // wheel moves are not continued: what is left is dropped
        wheel.moving = false;
        engine.clear();
        engine.release();
    }
    if (deferred != Deferred::Halt)
        return;
    deferred = Deferred::None;
    const Reply r{0, {}};
    sendReply(r);
    lastReply = formatReply(r);
}

bool Unit::Impl::spindleTurning() const
{
    const bool out0 = !(outputs & 0x01);
    if (!info->hasSpindleAddress7) // GVE84: the relay switches the spindle only as function 00
        return out0 && cfg.outputFunction[0] == OutputFunction::Spindle;
    return out0 && spindle > 0;
}

void Unit::Impl::noteSpindle()
{
    const bool cutting = engine.isMoving() && !engine.queue().front().isHoming &&
                         safety.intoWork(engine.position(), engine.headEnd());
    safety.spindle(spindleTurning(), engine.now(), cutting);
}

void Unit::Impl::observeSafety()
{
    safety.observe((kept || inta) && !engine.isMoving(), engine.now());
}

bool Unit::Impl::runBit() const
{
    return !engine.isIdle() || mpg != Mpg::Off || homing.has_value();
}

std::uint8_t Unit::Impl::st6() const
{
    return static_cast<std::uint8_t>((stopBit ? 0x01 : 0) | (freeBit ? 0x02 : 0) |
                                     (intcom ? 0x10 : 0) | (runBit() ? 0x40 : 0) |
                                     (inta ? 0x80 : 0));
}

} // namespace frezka::emulator
