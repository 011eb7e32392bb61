#include "commissionreport.h"

#include "protocol/checksum.h"
#include "protocol/variant.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

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

QString heading(const QString &title)
{
    return QStringLiteral("\n%1\n%2\n").arg(title, QString(title.size(), QLatin1Char('-')));
}

QString unitPart(const CommissionResult &r)
{
    QString t = heading(tr("Unit"));
    const auto &info = protocol::variantInfo(r.profileBefore.unit.variant);
    t += tr("port: %1\n").arg(q(r.port));
    t += tr("identified as: %1\n")
             .arg(r.variantId.empty()
                      ? tr("unknown")
                      : q(std::string(protocol::variantInfo(*protocol::variantFromId(r.variantId))
                                          .displayName)));
    t += tr("firmware: %1\n").arg(r.firmware.empty() ? tr("(no answer)") : q(r.firmware));
    t += tr("unit number: %1\n").arg(q(r.unitId));
    t += tr("profile: %1 (%2, firmware v%3)\n")
             .arg(q(r.profileBefore.name), q(std::string(info.displayName)))
             .arg(r.profileBefore.unit.firmwareVersion);
    return t;
}

QString stepsPart(const CommissionResult &r)
{
    QString t = heading(tr("Steps"));
    for (const auto &s : r.steps) {
        t += QStringLiteral("[%1] %2%3\n")
                 .arg(stepResultText(s.result), s.title, s.moves ? tr(" (moves)") : QString());
        if (!s.details.isEmpty())
            t += QStringLiteral("    %1\n").arg(s.details);
    }
    return t;
}

QString readingsPart(const CommissionResult &r)
{
    QString t = heading(tr("Protocol readings (docs/gve-protocol.md)"));
    if (r.readings.empty())
        t += tr("none checked\n");
    for (const auto &c : r.readings) {
        t += QStringLiteral("[%1] %2 %3\n").arg(stepResultText(c.result), q(c.section), c.reading);
        if (!c.details.isEmpty())
            t += QStringLiteral("    %1\n").arg(c.details);
    }
    return t;
}

QString linkPart(const CommissionResult &r)
{
    const LinkFigures &l = r.link;
    QString t = heading(tr("Link"));
    t += tr("baud: %1\n").arg(l.baud);
    for (const auto &c : l.classes)
        t += tr("%1 %2: %3 samples, %4 bytes each, round trip min %5 ms, median %6 ms, max %7 "
                "ms\n")
                 .arg(c.commandClass, q(c.example))
                 .arg(c.samples)
                 .arg(c.bytesPerExchange)
                 .arg(c.minMs, 0, 'f', 2)
                 .arg(c.medianMs, 0, 'f', 2)
                 .arg(c.maxMs, 0, 'f', 2);
    t += tr("bytes/s in packets (both ways): %1\n").arg(l.bytesPerS, 0, 'f', 0);
    t += tr("estimated adapter latency, one way: %1 ms\n").arg(l.latencyOneWayMs, 0, 'f', 2);
    t += tr("link.latencyMs: profile %1, proposed %2\n")
             .arg(l.profileLatencyMs, 0, 'f', 1)
             .arg(l.proposedLatencyMs, 0, 'f', 1);
    return t;
}

QString valueText(machine::EepromKind kind, double value)
{
    if (kind == machine::EepromKind::Byte)
        return q(protocol::hexByte(static_cast<std::uint8_t>(value)));
    return QString::number(value, 'g', 8);
}

QString eepromPart(const CommissionResult &r)
{
    QString t = heading(tr("EEPROM (decoded, against the profile)"));
    if (r.eeprom.empty())
        t += tr("not read\n");
    for (const auto &row : r.eeprom) {
        const QString unit =
            row.unitValue ? valueText(row.entry.kind, *row.unitValue) : tr("not read");
        t += tr("0x%1 %2: unit %3, profile %4 - %5\n")
                 .arg(q(protocol::hexByte(row.entry.address)), q(row.entry.what), unit,
                      valueText(row.entry.kind, row.entry.value),
                      row.matches ? tr("same") : tr("differs"));
        if (!row.unitValue)
            t += QStringLiteral("    %1\n").arg(q(row.unitRaw));
    }
    return t;
}

QString axesPart(const CommissionResult &r)
{
    QString t = heading(tr("Axes"));
    if (r.axes.empty())
        t += tr("no axis was moved\n");
    for (const auto &a : r.axes) {
        t += tr("%1: + %2, − %3, moved %4 mm each way, steps/mm %5")
                 .arg(QChar::fromLatin1(machine::kAxisLetters[static_cast<std::size_t>(a.axis)]))
                 .arg(stepResultText(a.plus), stepResultText(a.minus))
                 .arg(a.movedMm, 0, 'f', 3)
                 .arg(a.stepsPerMmBefore, 0, 'f', 4);
        if (a.measuredMm)
            t += tr(", measured %1 mm").arg(*a.measuredMm, 0, 'f', 3);
        if (a.stepsPerMmProposed)
            t += tr(", proposed steps/mm %1").arg(*a.stepsPerMmProposed, 0, 'f', 4);
        t += QLatin1Char('\n');
        if (!a.details.isEmpty())
            t += QStringLiteral("    %1\n").arg(a.details);
    }
    return t;
}

} // namespace

QString commissionReportText(const CommissionResult &r)
{
    QString t = tr("Frezka commissioning report\n===========================\n");
    t += unitPart(r) + stepsPart(r) + readingsPart(r) + linkPart(r) + eepromPart(r) + axesPart(r);
    t += heading(tr("Serial trace (docs/serial-trace.md)"));
    t += r.trace.empty() ? tr("not recorded\n") : q(r.trace);
    return t;
}

bool saveCommissionText(const QString &path, const QString &text, QString *error)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text.toUtf8()) < 0 || !file.commit()) {
        *error = tr("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

bool saveCommissionedProfile(const machine::MachineConfig &profile, const QString &path,
                             const QString &original, QString *error)
{
    if (!original.isEmpty() &&
        QFileInfo(path).absoluteFilePath() == QFileInfo(original).absoluteFilePath()) {
        *error = tr("the updated profile would replace %1; name a new file (--profile-out)")
                     .arg(original);
        return false;
    }
    return saveCommissionText(path, q(machine::toJson(profile)), error);
}

} // namespace frezka::session
