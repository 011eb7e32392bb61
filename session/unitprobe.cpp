#include "unitprobe.h"

#include "protocol/checksum.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace frezka::session {

namespace {

// lupdate files the tr() calls of this namespace under its name: the same context here.
QString tr(const char *text)
{
    return QCoreApplication::translate("frezka::session", text);
}

QString q(const std::string &s)
{
    return QString::fromStdString(s);
}

// Checksums off, whatever state an earlier session left them in: "%-,CF" is valid framing
// with checksums on, and harmless (answered or refused) with them off.
void checksumsOff(UnitChannel &channel)
{
    channel.sendBytes("!0%-,CF\r", 0.5);
    channel.setChecksums(false);
}

} // namespace

void identifyUnit(ProbeContext &context, CommissionResult &result)
{
    CommissionStep &step = *result.step("identify");
    UnitChannel &ch = context.channel;
    checksumsOff(ch);
    const auto version = ch.send("?");
    if (!version.reply || !version.reply->ok() || version.reply->values.empty()) {
        step.result = StepResult::DidNotHold;
        step.details = tr("The unit did not answer '?' (%1). Check the cable, the port and the "
                          "baud rate set on the unit.")
                           .arg(q(version.text()));
        return;
    }
    result.firmware = version.reply->values.front();
    const auto id = ch.send("Q");
    if (id.reply && id.reply->ok() && !id.reply->values.empty())
        result.unitId = id.reply->values.front();
    const auto variant = protocol::variantFromFirmware(result.firmware);
    const auto fw = protocol::firmwareVersion(result.firmware);
    const protocol::Variant v = variant.value_or(context.profile.unit.variant);
    context.features = protocol::featuresOf(v, fw);
    context.axisCount = protocol::variantInfo(v).axisCount;
    context.identified = true;
    result.variantId = variant ? std::string(protocol::variantInfo(*variant).id) : std::string();
    const auto &wanted = protocol::variantInfo(context.profile.unit.variant);
    QStringList problems;
    if (!variant)
        problems << tr("the firmware '%1' names no known unit").arg(q(result.firmware));
    else if (*variant != context.profile.unit.variant) // queue, rates and EEPROM differ too
        problems << tr("the unit is a %1, the profile is for a %2")
                        .arg(q(std::string(protocol::variantInfo(*variant).displayName)),
                             q(std::string(wanted.displayName)));
    if (fw && *fw != context.profile.unit.firmwareVersion)
        problems << tr("the firmware is v%1, the profile says v%2 (unit.firmwareVersion)")
                        .arg(*fw)
                        .arg(context.profile.unit.firmwareVersion);
    if (context.features.mpg)
        ch.send("Y-"); // vectors (even L0,0,0) are refused while the MPG holds RUN
    step.details = tr("Firmware '%1', unit number '%2'.").arg(q(result.firmware), q(result.unitId));
    if (problems.isEmpty()) {
        step.result = StepResult::Held;
    } else {
        step.result = StepResult::DidNotHold;
        step.details +=
            QLatin1Char(' ') + problems.join(QStringLiteral("; ")) +
            tr(". Correct the profile (unit.variant, unit.firmwareVersion) to the unit.");
    }
}

namespace {

LinkClassFigure timeClass(UnitChannel &ch, QString name, const std::string &bytes, int samples)
{
    LinkClassFigure f;
    f.commandClass = std::move(name);
    f.example = bytes.substr(0, bytes.find('\r'));
    std::vector<double> ms;
    for (int i = 0; i < samples; ++i) {
        const long long before = ch.line().bytesOut() + ch.line().bytesIn();
        const auto e = ch.sendBytes(bytes);
        if (e.timedOut || !e.reply)
            continue;
        ms.push_back(e.roundTripMs);
        f.bytesPerExchange = static_cast<int>(ch.line().bytesOut() + ch.line().bytesIn() - before);
    }
    f.samples = static_cast<int>(ms.size());
    if (ms.empty())
        return f;
    std::sort(ms.begin(), ms.end());
    f.minMs = ms.front();
    f.maxMs = ms.back();
    f.medianMs = ms[ms.size() / 2];
    return f;
}

std::string packetOfBrakes(const UnitChannel &ch, int count, int brake)
{
    std::string bytes = ch.frame("*S");
    for (int i = 0; i < count; ++i)
        bytes += ch.frame("B" + std::to_string(brake));
    return bytes + ch.frame("*E" + std::to_string(count));
}

} // namespace

void measureLink(ProbeContext &context, CommissionResult &result)
{
    CommissionStep &step = *result.step("link");
    UnitChannel &ch = context.channel;
    LinkFigures &link = result.link;
    link.baud = context.baud;
    link.profileLatencyMs = context.profile.link.latencyMs;
    const int brake = protocol::variantInfo(context.profile.unit.variant).resetBrakeSpeed;
    link.classes.push_back(timeClass(ch, tr("status (F)"), ch.frame("F"), 20));
    link.classes.push_back(
        timeClass(ch, tr("position (PF/P4)"), ch.frame(context.axisCount == 4 ? "P4" : "PF"), 20));
    link.classes.push_back(timeClass(ch, tr("EEPROM byte (ER)"), ch.frame("ER05"), 10));
    link.classes.push_back(timeClass(ch, tr("packet of 10 B"), packetOfBrakes(ch, 10, brake), 5));
    const LinkClassFigure &status = link.classes.front();
    const LinkClassFigure &packet = link.classes.back();
    if (status.samples == 0 || packet.samples == 0) {
        step.result = StepResult::NotChecked;
        step.details = tr("The unit did not answer the timed commands.");
        return;
    }
    link.bytesPerS = packet.bytesPerExchange / (packet.medianMs / 1000.0);
    // The shortest status round trip is the wire time of its bytes plus the adapter's latency
    // both ways (and the unit's reaction, which is far below a millisecond).
    const double wireMs = status.bytesPerExchange * 10.0 * 1000.0 / std::max(1, context.baud);
    link.latencyOneWayMs = std::max(0.0, (status.minMs - wireMs) / 2.0);
    link.proposedLatencyMs = std::clamp(std::ceil(link.latencyOneWayMs * 2.0) / 2.0, 0.5, 100.0);
    result.profileAfter.link.latencyMs = link.proposedLatencyMs;
    step.details = tr("Adapter latency about %1 ms each way; %2 bytes/s in packets; proposed "
                      "link.latencyMs = %3 (the profile had %4).")
                       .arg(link.latencyOneWayMs, 0, 'f', 2)
                       .arg(link.bytesPerS, 0, 'f', 0)
                       .arg(link.proposedLatencyMs, 0, 'f', 1)
                       .arg(link.profileLatencyMs, 0, 'f', 1);
    if (link.latencyOneWayMs <= link.profileLatencyMs) {
        step.result = StepResult::Held;
    } else {
        step.result = StepResult::DidNotHold;
        step.details += QLatin1Char(' ') +
                        tr("The link is slower than the profile says: the planner would pace "
                           "jobs for a faster line. Save the proposed profile.");
    }
}

namespace {

// Reads one entry: ERaa (byte, hex), EFRaa (float), EURaa (uint32), addresses in hex.
void readEntry(UnitChannel &ch, EepromRow &row)
{
    const std::string address = protocol::hexByte(row.entry.address);
    std::string body;
    switch (row.entry.kind) {
    case machine::EepromKind::Byte:
        body = "ER" + address;
        break;
    case machine::EepromKind::Float:
        body = "EFR" + address;
        break;
    case machine::EepromKind::Uint32:
        body = "EUR" + address;
        break;
    }
    const auto e = ch.send(body);
    row.unitRaw = e.text();
    if (!e.reply || !e.reply->ok())
        return;
    if (row.entry.kind == machine::EepromKind::Byte) {
        if (auto b = e.reply->hexValue())
            row.unitValue = *b;
    } else if (auto r = e.reply->real()) {
        row.unitValue = *r;
    }
    if (row.unitValue)
        row.matches = std::abs(*row.unitValue - row.entry.value) <=
                      1e-4 * std::max(1.0, std::abs(row.entry.value));
}

} // namespace

void readEeprom(ProbeContext &context, CommissionResult &result)
{
    CommissionStep &step = *result.step("eeprom");
    int differ = 0;
    int unread = 0;
    for (const auto &entry : machine::eepromEntries(context.profile)) {
        EepromRow row;
        row.entry = entry;
        if (entry.kind != machine::EepromKind::Byte && !context.features.eepromFloat)
            row.unitRaw = tr("not on this firmware").toStdString();
        else
            readEntry(context.channel, row);
        if (!row.unitValue)
            ++unread;
        else if (!row.matches)
            ++differ;
        result.eeprom.push_back(std::move(row));
    }
    step.details = tr("%1 settings read, %2 differ from the profile, %3 could not be read.")
                       .arg(static_cast<int>(result.eeprom.size()) - unread)
                       .arg(differ)
                       .arg(unread);
    if (differ > 0)
        step.details +=
            QLatin1Char(' ') + tr("Write the profile's values with Machine › Unit configuration "
                                  "(EEPROM), or correct the profile.");
    step.result = differ > 0 || unread > 0 ? StepResult::DidNotHold : StepResult::Held;
}

void finishProbe(ProbeContext &context)
{
    if (context.channel.checksums())
        checksumsOff(context.channel);
}

} // namespace frezka::session

namespace frezka::session {

bool runUnitProbe(driver::Transport &transport, const machine::MachineConfig &profile, int baud,
                  CommissionResult &result, QString *error)
{
    RawLine line(transport);
    if (!line.open(5.0, error))
        return false;
    UnitChannel channel(line);
    ProbeContext context{channel, profile, baud, {}, 3, false};
    identifyUnit(context, result);
    if (!context.identified) {
        for (const char *id : {"readings", "link", "eeprom"}) {
            result.step(id)->result = StepResult::NotChecked;
            result.step(id)->details = tr("The unit was not identified.");
        }
        line.close();
        return true;
    }
    checkReadings(context, result);
    measureLink(context, result);
    readEeprom(context, result);
    finishProbe(context);
    line.close();
    return true;
}

} // namespace frezka::session
