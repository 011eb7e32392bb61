#include "commission.h"

#include "protocol/variant.h"

#include <QCoreApplication>

namespace frezka::session {

namespace {

// lupdate files the tr() calls of this namespace under its name: the same context here.
QString tr(const char *text)
{
    return QCoreApplication::translate("frezka::session", text);
}

CommissionStep make(std::string id, QString title, QString does, bool moves, bool needsOperator)
{
    CommissionStep s;
    s.id = std::move(id);
    s.title = std::move(title);
    s.does = std::move(does);
    s.moves = moves;
    s.needsOperator = needsOperator;
    return s;
}

} // namespace

QString stepResultText(StepResult result)
{
    switch (result) {
    case StepResult::Held:
        return tr("held");
    case StepResult::DidNotHold:
        return tr("did not hold");
    case StepResult::NotChecked:
        return tr("not checked");
    case StepResult::Skipped:
        return tr("skipped");
    }
    return {};
}

CommissionStep *CommissionResult::step(const std::string &id)
{
    for (auto &s : steps)
        if (s.id == id)
            return &s;
    return nullptr;
}

const CommissionStep *CommissionResult::step(const std::string &id) const
{
    for (const auto &s : steps)
        if (s.id == id)
            return &s;
    return nullptr;
}

std::vector<CommissionStep> commissionSteps(const machine::MachineConfig &profile)
{
    std::vector<CommissionStep> steps;
    steps.push_back(make("identify", tr("Identify the unit"),
                         tr("Asks the unit for its firmware (?) and its number (Q) and compares "
                            "them with the profile."),
                         false, false));
    steps.push_back(make("readings", tr("Check the protocol readings"),
                         tr("Checks the readings of the manuals that can be checked without "
                            "motion: checksums, @ and >, packet replies, error replies, EEPROM "
                            "reads."),
                         false, false));
    steps.push_back(make("link", tr("Measure the link"),
                         tr("Times round trips per command class, the bytes per second and the "
                            "adapter's latency, and proposes link.latencyMs."),
                         false, false));
    steps.push_back(make("eeprom", tr("Read the EEPROM"),
                         tr("Reads the unit's EEPROM settings, decodes them and compares them "
                            "with the profile (nothing is written)."),
                         false, false));
    const int axes = protocol::variantInfo(profile.unit.variant).axisCount;
    for (int a = 0; a < axes; ++a) {
        if (!profile.axes[static_cast<std::size_t>(a)].present)
            continue;
        const QString letter(QChar::fromLatin1(machine::kAxisLetters[static_cast<std::size_t>(a)]));
        steps.push_back(
            make("axis-" + std::string(1, static_cast<char>(std::tolower(
                                              machine::kAxisLetters[static_cast<std::size_t>(a)]))),
                 tr("Move axis %1").arg(letter),
                 tr("Moves axis %1 a little in + and then back in − at a low speed; "
                    "you confirm the direction and enter the distance you measured, "
                    "which corrects its steps per mm.")
                     .arg(letter),
                 true, true));
    }
    steps.push_back(make("switches", tr("Test the home and limit switches"),
                         tr("You press each switch by hand; the step watches its input."), false,
                         true));
    if (protocol::variantInfo(profile.unit.variant).hasSpindleAddress7)
        steps.push_back(make("stop", tr("Test the STOP button"),
                             tr("You press the STOP button; the step watches its input."), false,
                             true));
    steps.push_back(make("spindle", tr("Run the spindle at two speeds"),
                         tr("Switches the spindle on at a quarter and at half of its maximum "
                            "speed, then off; you confirm it turned."),
                         true, true));
    steps.push_back(make("outputs", tr("Switch the outputs"),
                         tr("Switches each output the profile uses (coolant, air ...) on and off; "
                            "you confirm it switched."),
                         true, true));
    steps.push_back(make("homing", tr("Home the machine"),
                         tr("Homes the axes the profile homes, in its order (last, when the "
                            "switches are known to work)."),
                         true, true));
    return steps;
}

CommissionResult startCommission(const machine::MachineConfig &profile, const std::string &port)
{
    CommissionResult r;
    r.port = port;
    r.steps = commissionSteps(profile);
    r.profileBefore = profile;
    r.profileAfter = profile;
    return r;
}

void skipOperatorSteps(CommissionResult &result, const QString &why)
{
    for (auto &s : result.steps) {
        if (s.needsOperator && s.result == StepResult::NotChecked) {
            s.result = StepResult::Skipped;
            s.details = why;
        }
    }
}

} // namespace frezka::session
