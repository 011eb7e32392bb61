// The adopted readings of docs/gve-protocol.md (and the rules around them) that can be checked
// without moving anything: each check sends what the reading is about and compares the reply
// with what the reading says. Declared in unitprobe.h.

#include "session/unitprobe.h"

#include "protocol/checksum.h"

#include <QCoreApplication>

namespace frezka::session {

namespace {

// lupdate files the tr() calls of this namespace under its name: the same context here.
QString tr(const char *text)
{
    return QCoreApplication::translate("frezka::session", text);
}

struct Checker
{
    ProbeContext &context;
    std::vector<ReadingCheck> &out;
    QStringList seen; // the exchanges of the check being made

    UnitChannel::Exchange send(const std::string &body, int address = 0)
    {
        auto e = context.channel.send(body, address);
        seen << QString::fromStdString(e.text());
        return e;
    }
    UnitChannel::Exchange sendBytes(const std::string &bytes)
    {
        auto e = context.channel.sendBytes(bytes);
        seen << QString::fromStdString(e.text());
        return e;
    }
    // The index (@), -1 when the reply is not "0,n".
    int index()
    {
        const auto e = send("@");
        return e.reply && e.reply->ok() ? static_cast<int>(e.reply->decimal().value_or(-1)) : -1;
    }
    void add(const char *section, QString reading, bool held, bool checked = true)
    {
        ReadingCheck c;
        c.section = section;
        c.reading = std::move(reading);
        c.result =
            !checked ? StepResult::NotChecked : (held ? StepResult::Held : StepResult::DidNotHold);
        c.details = seen.join(QStringLiteral("; "));
        out.push_back(std::move(c));
        seen.clear();
    }
    void notChecked(const char *section, QString reading, QString why)
    {
        seen.clear();
        seen << why;
        add(section, std::move(reading), false, false);
    }
};

void checkChecksums(Checker &k)
{
    UnitChannel &ch = k.context.channel;
    const auto on = k.sendBytes("!0%+\r");
    const auto decoded = protocol::decodeReply(on.raw, protocol::ChecksumMode::On);
    const bool held = decoded.reply && decoded.reply->ok() && decoded.checksummed;
    if (held)
        ch.setChecksums(true);
    k.add("§2.1", tr("%+ switches checksums on and its reply already carries one (0,5C)"), held);
    if (!held)
        return;
    const int before = k.index();
    std::string bad = "!0F,";
    const std::uint8_t right = protocol::checksum(bad);
    bad += protocol::hexByte(static_cast<std::uint8_t>(right + 1)) + "\r";
    const auto refused = k.sendBytes(bad);
    const int after = k.index();
    k.add("§2.1, §8",
          tr("a command with a wrong checksum is answered 4 and does not advance the index (@)"),
          refused.code() == 4 && before >= 0 && after == before);
}

void checkIndex(Checker &k)
{
    const int first = k.index();
    k.send("F");
    const int second = k.index();
    const int third = k.index();
    k.add("§8", tr("every valid command advances the index by one, @ itself does not"),
          first >= 0 && second == (first + 1) % 256 && third == second);
    const auto position = k.send(k.context.axisCount == 4 ? "P4" : "PF");
    const auto repeat = k.send(">");
    const int last = k.index();
    k.add("§8", tr("> repeats the last reply without executing the command again"),
          position.reply && !position.raw.empty() && repeat.raw == position.raw &&
              last == (third + 1) % 256);
}

void checkErrorCodes(Checker &k)
{
    k.add("§2", tr("an unknown command is answered 3"), k.send("U").code() == 3);
    k.add("§2", tr("a malformed parameter is answered 4"), k.send("Tx").code() == 4);
    k.add("§2", tr("a parameter out of range is answered 5 (T99)"), k.send("T99").code() == 5);
    const auto lf = k.sendBytes(k.context.channel.frame("F") + "\n");
    const int index = k.index();
    k.add("§2", tr("a LF after the CR is ignored"),
          lf.reply && lf.reply->ok() && index >= 0 && k.context.channel.line().strayLines() == 0);
}

void checkPackets(Checker &k)
{
    UnitChannel &ch = k.context.channel;
    const std::string brake =
        "B" + std::to_string(protocol::variantInfo(k.context.profile.unit.variant).resetBrakeSpeed);
    const auto whole =
        k.sendBytes(ch.frame("*S") + ch.frame(brake) + ch.frame(brake) + ch.frame("*E2"));
    k.add("§2.2", tr("a packet is answered once, at its end, with the number of commands (0,2)"),
          whole.reply && whole.reply->ok() && whole.reply->decimal() == 2);
    const auto partial = k.sendBytes(ch.frame("*S") + ch.frame(brake) + ch.frame("B0") +
                                     ch.frame(brake) + ch.frame("*E3"));
    k.add("§2.2",
          tr("a packet whose command fails stops there and answers that code and the number "
             "accepted before it (5,1)"),
          partial.code() == 5 && partial.reply->decimal() == 1);
}

void checkComponents(Checker &k)
{
    if (k.context.axisCount == 4) {
        const auto three = k.send("L0,0,0");
        const auto two = k.send("L0,0");
        k.add("§4",
              tr("a 4-axis unit takes L with three components (A = 0); fewer than three is "
                 "answered 4"),
              three.code() == 0 && two.code() == 4);
    } else {
        const auto four = k.send("L0,0,0,0");
        const auto two = k.send("L0,0");
        k.add("§4", tr("a 3-axis unit answers 4 to a vector of four components or of two"),
              four.code() == 4 && two.code() == 4);
    }
}

void checkEepromReads(Checker &k)
{
    const auto byte = k.send("ER05");
    k.add("§12", tr("ERaa reads an EEPROM byte as two hex digits"),
          byte.reply && byte.reply->ok() && byte.reply->hexValue().has_value());
    if (!k.context.features.eepromFloat) {
        k.notChecked("§12", tr("float and 32-bit EEPROM values travel as decimal text"),
                     tr("the unit's firmware has no EFR/EUR"));
        return;
    }
    const auto real = k.send("EFR30");
    const auto whole = k.send("EUR48");
    k.add("§12", tr("float and 32-bit EEPROM values travel as decimal text"),
          real.reply && real.reply->ok() && real.reply->real().has_value() && whole.reply &&
              whole.reply->ok() && whole.reply->decimal().has_value());
}

} // namespace

void checkReadings(ProbeContext &context, CommissionResult &result)
{
    CommissionStep &step = *result.step("readings");
    Checker k{context, result.readings, {}};
    checkChecksums(k);
    checkIndex(k);
    checkErrorCodes(k);
    checkPackets(k);
    checkComponents(k);
    checkEepromReads(k);
    const QString motion = tr("needs motion or a reset; not checked here");
    k.notChecked("§3, §4", tr("the speed mode after a reset is VN"), motion);
    k.notChecked("§4", tr("VL limits are in pulses/s"), motion);
    k.notChecked("§6", tr("a home switch not found within the travel is answered 5"),
                 tr("the homing step shows it"));
    int held = 0, failed = 0;
    for (const auto &c : result.readings) {
        held += c.result == StepResult::Held;
        failed += c.result == StepResult::DidNotHold;
    }
    step.result = failed > 0 ? StepResult::DidNotHold : StepResult::Held;
    step.details = tr("%1 readings held, %2 did not hold, %3 not checked.")
                       .arg(held)
                       .arg(failed)
                       .arg(static_cast<int>(result.readings.size()) - held - failed);
    if (failed > 0)
        step.details += QLatin1Char(' ') + tr("Send the report (README: when a unit does "
                                              "something unexpected).");
}

} // namespace frezka::session
