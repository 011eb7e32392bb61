// The driver's messages in words (drivererror.h): the catalogue of fixed phrases, the English
// text and the wording in the user's language. The code table is in drivercodes.cpp.

#include "drivererror.h"

#include <QCoreApplication>

#include <cmath>
#include <cstdio>
#include <cstring>

namespace frezka::driver {

namespace {

// Fixed phrases the driver puts into arguments: the actions of unitError(), the unit's reply
// texts (protocol::replyCodeText), the mode names (machineModeName). Listed for lupdate;
// translatedPhrase() looks any argument up in the catalogue.
[[maybe_unused]] constexpr const char *kPhrases[] = {
    // actions
    QT_TRANSLATE_NOOP("frezka::driver", "applying the new speed (XA)"),
    QT_TRANSLATE_NOOP("frezka::driver", "arming the probe input"),
    QT_TRANSLATE_NOOP("frezka::driver", "continuing (G)"),
    QT_TRANSLATE_NOOP("frezka::driver", "disarming the probe input"),
    QT_TRANSLATE_NOOP("frezka::driver", "dropping the queue (D)"),
    QT_TRANSLATE_NOOP("frezka::driver", "dropping the queue (D) off the planned path"),
    QT_TRANSLATE_NOOP("frezka::driver", "ending the jog (D)"),
    QT_TRANSLATE_NOOP("frezka::driver", "identifying the unit ('?')"),
    QT_TRANSLATE_NOOP("frezka::driver", "identifying the unit ('Q')"),
    QT_TRANSLATE_NOOP("frezka::driver", "jogging"),
    QT_TRANSLATE_NOOP("frezka::driver", "keeping the queue (K)"),
    QT_TRANSLATE_NOOP("frezka::driver", "lifting the tool"),
    QT_TRANSLATE_NOOP("frezka::driver", "lowering the tool"),
    QT_TRANSLATE_NOOP("frezka::driver", "pausing (H)"),
    QT_TRANSLATE_NOOP("frezka::driver", "position poll"),
    QT_TRANSLATE_NOOP("frezka::driver", "probe move"),
    QT_TRANSLATE_NOOP("frezka::driver", "raw command"),
    QT_TRANSLATE_NOOP("frezka::driver", "re-sending the job's speed settings"),
    QT_TRANSLATE_NOOP("frezka::driver", "reading the EEPROM"),
    QT_TRANSLATE_NOOP("frezka::driver", "reading the final position"),
    QT_TRANSLATE_NOOP("frezka::driver", "reading the position"),
    QT_TRANSLATE_NOOP("frezka::driver", "reading the probe input"),
    QT_TRANSLATE_NOOP("frezka::driver", "reading the probe position"),
    QT_TRANSLATE_NOOP("frezka::driver", "reading the probe result"),
    QT_TRANSLATE_NOOP("frezka::driver", "reading the status"),
    QT_TRANSLATE_NOOP("frezka::driver", "restoring the queue (R)"),
    QT_TRANSLATE_NOOP("frezka::driver", "returning to the planned path"),
    QT_TRANSLATE_NOOP("frezka::driver", "setting the feed override (XM)"),
    QT_TRANSLATE_NOOP("frezka::driver", "setting the jog speed"),
    QT_TRANSLATE_NOOP("frezka::driver", "setting the new speed"),
    QT_TRANSLATE_NOOP("frezka::driver", "setting the speed to return to the path"),
    QT_TRANSLATE_NOOP("frezka::driver", "setting the spindle"),
    QT_TRANSLATE_NOOP("frezka::driver", "starting the spindle"),
    QT_TRANSLATE_NOOP("frezka::driver", "status"),
    QT_TRANSLATE_NOOP("frezka::driver", "status poll"),
    QT_TRANSLATE_NOOP("frezka::driver", "stopping (H)"),
    QT_TRANSLATE_NOOP("frezka::driver", "stopping (H) off the planned path"),
    QT_TRANSLATE_NOOP("frezka::driver", "stopping the jog (H)"),
    QT_TRANSLATE_NOOP("frezka::driver", "stopping the probe move (H)"),
    QT_TRANSLATE_NOOP("frezka::driver", "stopping the spindle"),
    QT_TRANSLATE_NOOP("frezka::driver", "switching checksums"),
    QT_TRANSLATE_NOOP("frezka::driver", "switching outputs"),
    QT_TRANSLATE_NOOP("frezka::driver", "switching the MPG"),
    QT_TRANSLATE_NOOP("frezka::driver", "switching the MPG off"),
    QT_TRANSLATE_NOOP("frezka::driver", "testing packets"),
    QT_TRANSLATE_NOOP("frezka::driver", "raising queued speeds (XU)"),
    QT_TRANSLATE_NOOP("frezka::driver", "lowering queued speeds (XD)"),
    QT_TRANSLATE_NOOP("frezka::driver", "zeroing the counters (N)"),
    QT_TRANSLATE_NOOP("frezka::driver", "setting T"),
    QT_TRANSLATE_NOOP("frezka::driver", "setting VN"),
    QT_TRANSLATE_NOOP("frezka::driver", "setting the interrupt mask"),
    QT_TRANSLATE_NOOP("frezka::driver", "setting the input polarity"),
    QT_TRANSLATE_NOOP("frezka::driver", "Pause"), QT_TRANSLATE_NOOP("frezka::driver", "Resume"),
    QT_TRANSLATE_NOOP("frezka::driver", "Abort"), QT_TRANSLATE_NOOP("frezka::driver", "Homing"),
    QT_TRANSLATE_NOOP("frezka::driver", "Jogging"),
    QT_TRANSLATE_NOOP("frezka::driver", "Stopping the jog"),
    QT_TRANSLATE_NOOP("frezka::driver", "Writing the EEPROM"),
    QT_TRANSLATE_NOOP("frezka::driver", "Lifting the tool"),
    QT_TRANSLATE_NOOP("frezka::driver", "Lowering the tool"),
    QT_TRANSLATE_NOOP("frezka::driver", "Switching the MPG"),
    QT_TRANSLATE_NOOP("frezka::driver", "Setting the spindle"),
    QT_TRANSLATE_NOOP("frezka::driver", "Switching outputs"),
    // the unit's replies
    QT_TRANSLATE_NOOP("frezka::driver", "OK"), QT_TRANSLATE_NOOP("frezka::driver", "queue full"),
    QT_TRANSLATE_NOOP("frezka::driver", "command not received completely in time"),
    QT_TRANSLATE_NOOP("frezka::driver", "unknown command"),
    QT_TRANSLATE_NOOP("frezka::driver", "syntax error"),
    QT_TRANSLATE_NOOP("frezka::driver", "parameter out of range"),
    QT_TRANSLATE_NOOP("frezka::driver", "nothing to continue"),
    QT_TRANSLATE_NOOP("frezka::driver", "not allowed while a vector runs"),
    // modes
    QT_TRANSLATE_NOOP("frezka::driver", "Disconnected"),
    QT_TRANSLATE_NOOP("frezka::driver", "Connecting"), QT_TRANSLATE_NOOP("frezka::driver", "Idle"),
    QT_TRANSLATE_NOOP("frezka::driver", "Running"), QT_TRANSLATE_NOOP("frezka::driver", "Stopping"),
    QT_TRANSLATE_NOOP("frezka::driver", "Paused"),
    QT_TRANSLATE_NOOP("frezka::driver", "Tool lifted"),
    QT_TRANSLATE_NOOP("frezka::driver", "Alarm"), QT_TRANSLATE_NOOP("frezka::driver", "Link lost"),
    // link reasons (LinkEngine's phrases)
    QT_TRANSLATE_NOOP("frezka::driver", "the link was closed"),
    QT_TRANSLATE_NOOP("frezka::driver", "incomplete reply"),
    QT_TRANSLATE_NOOP("frezka::driver", "garbled reply"),
    QT_TRANSLATE_NOOP("frezka::driver", "doubtful reply"),
    QT_TRANSLATE_NOOP("frezka::driver", "garbled reply to '@'"),
    QT_TRANSLATE_NOOP("frezka::driver", "garbled repeated reply"),
    QT_TRANSLATE_NOOP("frezka::driver", "doubtful repeated reply"),
    QT_TRANSLATE_NOOP("frezka::driver", "no reply to recovery query"),
    QT_TRANSLATE_NOOP("frezka::driver", "line %1"),
    // refusals' reasons
    QT_TRANSLATE_NOOP("frezka::driver", "no reply"), QT_TRANSLATE_NOOP("frezka::driver", "setup"),
    // the arguments the protocol's check names (protocol/validate.cpp)
    QT_TRANSLATE_NOOP("frezka::driver", "component"),
    QT_TRANSLATE_NOOP("frezka::driver", "pause (ms)"),
    QT_TRANSLATE_NOOP("frezka::driver", "SHORT threshold"),
    QT_TRANSLATE_NOOP("frezka::driver", "acceleration"),
    QT_TRANSLATE_NOOP("frezka::driver", "speed"),
    QT_TRANSLATE_NOOP("frezka::driver", "brake speed"),
    QT_TRANSLATE_NOOP("frezka::driver", "multiplier (%)"),
    QT_TRANSLATE_NOOP("frezka::driver", "counter"), QT_TRANSLATE_NOOP("frezka::driver", "travel"),
    QT_TRANSLATE_NOOP("frezka::driver", "speed toward the switch"),
    QT_TRANSLATE_NOOP("frezka::driver", "back-off travel"),
    QT_TRANSLATE_NOOP("frezka::driver", "speed off the switch"),
    QT_TRANSLATE_NOOP("frezka::driver", "EEPROM address"),
    QT_TRANSLATE_NOOP("frezka::driver", "byte"), QT_TRANSLATE_NOOP("frezka::driver", "value"),
    QT_TRANSLATE_NOOP("frezka::driver", "output byte"),
    QT_TRANSLATE_NOOP("frezka::driver", "status number"),
    QT_TRANSLATE_NOOP("frezka::driver", "status byte"),
    QT_TRANSLATE_NOOP("frezka::driver", "packet command count"),
    QT_TRANSLATE_NOOP("frezka::driver", "spindle (per mille)")};

// %1 .. %9 replaced by the arguments (a missing one by nothing), left to right; the one after
// the last argument by the detail's text when there is one.
std::string fill(const std::string &pattern, const DriverMessage &m)
{
    std::string out;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] == '%' && i + 1 < pattern.size() && pattern[i + 1] >= '1' &&
            pattern[i + 1] <= '9') {
            const auto n = static_cast<std::size_t>(pattern[i + 1] - '1');
            if (n < m.args.size())
                out += m.args[n];
            else if (n == m.args.size() && !m.detail.empty())
                out += englishText(m.detail.front());
            ++i;
        } else {
            out += pattern[i];
        }
    }
    return out;
}

// The same in the user's language: each argument through the phrase catalogue, the detail
// worded in the user's language too.
QString fill(const QString &pattern, const DriverMessage &m)
{
    QString out;
    for (qsizetype i = 0; i < pattern.size(); ++i) {
        const QChar c = pattern[i];
        if (c == QLatin1Char('%') && i + 1 < pattern.size() && pattern[i + 1] >= QLatin1Char('1') &&
            pattern[i + 1] <= QLatin1Char('9')) {
            const auto n = static_cast<std::size_t>(pattern[i + 1].unicode() - '1');
            if (n < m.args.size())
                out += translatedPhrase(m.args[n]);
            else if (n == m.args.size() && !m.detail.empty())
                out += translatedText(m.detail.front());
            ++i;
        } else {
            out += c;
        }
    }
    return out;
}

} // namespace

std::string englishText(const DriverMessage &message, bool withHint)
{
    std::string text = fill(std::string(driverTemplate(message.code)), message);
    if (withHint && *driverHint(message.code))
        text += ". " + fill(std::string(driverHint(message.code)), message);
    return text;
}

QString translatedPhrase(const std::string &phrase)
{
    if (phrase.empty())
        return {};
    // "line 12" (detail::lineText): the one phrase with a number in it.
    if (phrase.rfind("line ", 0) == 0 && phrase.size() > 5 &&
        phrase.find_first_not_of("0123456789", 5) == std::string::npos)
        return QCoreApplication::translate("frezka::driver", "line %1")
            .arg(QString::fromStdString(phrase.substr(5)));
    return QCoreApplication::translate("frezka::driver", phrase.c_str());
}

QString translatedText(const DriverMessage &message, bool withHint)
{
    QString text =
        fill(QCoreApplication::translate("frezka::driver", driverTemplate(message.code)), message);
    const char *hint = driverHint(message.code);
    if (withHint && *hint)
        text += QStringLiteral(". ") +
                fill(QCoreApplication::translate("frezka::driver", hint), message);
    return text;
}

std::string numberText(double value)
{
    if (std::isfinite(value) && value == std::round(value) && std::abs(value) < 1e15)
        return std::to_string(static_cast<long long>(value));
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", value);
    return buf;
}

} // namespace frezka::driver
