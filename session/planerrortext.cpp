#include "planerrortext.h"

#include <QCoreApplication>

// The texts keep their context "frezka::gui::Plan" (where they were first written), so their
// translations stay as they are.
namespace frezka::session {
namespace {

const char *planErrorWhat(machine::PlanErrorCode code)
{
    using C = machine::PlanErrorCode;
    switch (code) {
    case C::SoftLimit:
        return QT_TRANSLATE_NOOP("frezka::gui::Plan",
                                 "the move leaves the machine's travel (soft limits); check the "
                                 "work zero and the program");
    case C::AbsentAxis:
        return QT_TRANSLATE_NOOP("frezka::gui::Plan",
                                 "the program moves an axis this machine does not have");
    case C::CounterOverflow:
        return QT_TRANSLATE_NOOP("frezka::gui::Plan",
                                 "the position is beyond the unit's step counters");
    case C::NoFeed:
        return QT_TRANSLATE_NOOP("frezka::gui::Plan", "a feed move has no feed rate (F)");
    case C::SpindleTooFast:
        return QT_TRANSLATE_NOOP("frezka::gui::Plan",
                                 "the spindle speed (S) is above the machine's maximum");
    case C::Unsupported:
        return QT_TRANSLATE_NOOP("frezka::gui::Plan", "the unit cannot do this");
    case C::FeedCapped:
        return QT_TRANSLATE_NOOP("frezka::gui::Plan",
                                 "the feed is above what the machine's axes can do; it runs "
                                 "slower than programmed");
    }
    return "";
}

} // namespace

QString planErrorText(const QString &fileName, const machine::PlanError &error)
{
    const QString what =
        QCoreApplication::translate("frezka::gui::Plan", planErrorWhat(error.code));
    if (error.line == 0)
        return QCoreApplication::translate("frezka::gui::Plan", "%1: %2 (%3)")
            .arg(fileName, what, QString::fromStdString(error.message));
    return QCoreApplication::translate("frezka::gui::Plan", "%1:%2: %3 (%4)")
        .arg(fileName)
        .arg(error.line)
        .arg(what, QString::fromStdString(error.message));
}

} // namespace frezka::session
