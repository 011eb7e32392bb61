// Units on the whole main window (issue 16 item 6, workflowfixture.h): inch chosen in Settings ›
// Application shows the DRO, the jog steps and feed, the status panel's feeds and the speed
// plot in inches, while the wire and the unit stay in steps of mm: a 0.1 in jog step puts
// 2.54 mm of steps on the wire, the DRO reads the unit's counters converted, a G20 program is
// named as such and its feed is shown in in/min; back to mm, everything reads mm again.

#include "workflowfixture.h"

#include "gui/displayunits.h"
#include "gui/speedplot.h"
#include "gui/statuspanel.h"

#include <QComboBox>
#include <QDoubleSpinBox>

class WorkflowUnitsTest : public WorkflowFixture
{
    Q_OBJECT

    QString label(QWidget *parent, const char *name) const
    {
        auto *l = parent->findChild<QLabel *>(QLatin1String(name));
        return l ? l->text() : QStringLiteral("<no %1>").arg(QLatin1String(name));
    }
    // The unit's counter of an axis, in inches with the DRO's 4 decimals.
    QString countersInInch(int axis) const
    {
        const double mm = double(state().positionSteps[std::size_t(axis)]) /
                          m_window->profile().axes[std::size_t(axis)].stepsPerMm;
        return QString::number(mm / 25.4, 'f', 4);
    }
    void chooseUnits(LengthUnit unit)
    {
        SettingsDialog *settings = m_window->openSettings();
        auto *combo = settings->findChild<QComboBox *>(QStringLiteral("displayUnits"));
        QVERIFY(combo);
        const int i = combo->findData(int(unit));
        combo->setCurrentIndex(i);
        emit combo->activated(i); // as the operator's choice
        settings->close();
    }

private slots:
    void homeFirst()
    {
        QVERIFY(waitIdle());
        QVERIFY(m_window->dro()->findChildren<QLabel *>().size() > 0);
        QCOMPARE(displayUnit(), LengthUnit::Mm); // the default
        button(m_window->jogPanel(), "homeAll")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().homed && state().mode == MachineMode::Idle,
                                 kMachineTimeoutMs);
    }

    void inchesAreShownWhileTheWireStaysInSteps()
    {
        chooseUnits(LengthUnit::Inch);
        QCOMPARE(QSettings().value(QStringLiteral("display/units")).toString(),
                 QStringLiteral("inch"));
        // The jog: 0.1 in is 2.54 mm of steps on the wire and on the unit's counters.
        JogPanel *jog = m_window->jogPanel();
        auto *step = jog->findChild<QRadioButton *>(QStringLiteral("jogStep3"));
        QCOMPARE(step->text(), QStringLiteral("0.1"));
        step->click();
        QCOMPARE(jog->stepMm(), 2.54);
        auto *feed = jog->findChild<QDoubleSpinBox *>(QStringLiteral("jogFeed"));
        QVERIFY(feed->suffix().contains(QStringLiteral("in/min")));
        const std::int64_t x0 = state().positionSteps[0];
        WireTap wire;
        tapWire(wire);
        button(jog, "jogXPlus")->click();
        QTRY_COMPARE_WITH_TIMEOUT(state().positionSteps[0], x0 + steps(0, 2.54), kMachineTimeoutMs);
        QVERIFY(waitIdle());
        QVERIFY2(wire.first(QRegularExpression(
                     QStringLiteral("!0L%1,0,0(,0)?(,[0-9A-F]{2})?").arg(steps(0, 2.54)))) >= 0,
                 qPrintable(wire.sent.join(QLatin1Char('|'))));
        // The DRO reads the counters in inches (4 decimals) and says so.
        QTRY_COMPARE(m_window->dro()->machineText(0), countersInInch(0));
        QVERIFY(m_window->dro()->machineText(0) != QStringLiteral("0.0000"));
        QVERIFY(label(m_window->dro(), "droWorkX").count(QLatin1Char('.')) == 1);
        // A G20 program: named as inch, its feed shown in in/min while it runs, and it moves the
        // unit by its inches in mm steps.
        QVERIFY(
            load(writeProgram(QStringLiteral("inch.nc"), "G20 G91\nG1 X2 F40\nG1 Y0.5\nG90 M2\n")));
        QVERIFY2(label(m_window.get(), "programFile").contains(QStringLiteral("G20")),
                 qPrintable(label(m_window.get(), "programFile")));
        QVERIFY2(m_window->speedPlot()->axisText().startsWith(QStringLiteral("in/min")),
                 qPrintable(m_window->speedPlot()->axisText()));
        const std::int64_t xs = state().positionSteps[0], ys = state().positionSteps[1];
        m_window->runProgram();
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Running, kMachineTimeoutMs);
        QTRY_VERIFY2_WITH_TIMEOUT(
            label(m_window->statusPanel(), "statusProgrammedFeed")
                .contains(QStringLiteral("programmed 40.0 in/min")),
            qPrintable(label(m_window->statusPanel(), "statusProgrammedFeed")), 20000);
        QVERIFY(label(m_window->statusPanel(), "statusFeed").endsWith(QStringLiteral(" in/min")));
        QVERIFY(waitIdle());
        QCOMPARE(state().positionSteps[0], xs + steps(0, 2 * 25.4));
        QCOMPARE(state().positionSteps[1], ys + steps(1, 0.5 * 25.4));
        QTRY_COMPARE(m_window->dro()->machineText(0), countersInInch(0));
        QTRY_COMPARE(m_window->dro()->machineText(1), countersInInch(1));
    }

    void backToMillimetres()
    {
        chooseUnits(LengthUnit::Mm);
        const double mm = double(state().positionSteps[0]) / m_window->profile().axes[0].stepsPerMm;
        QCOMPARE(m_window->dro()->machineText(0), QString::number(mm, 'f', 3));
        QCOMPARE(m_window->jogPanel()->stepMm(), 10.0); // the same place in the row: 10 mm
        QVERIFY(m_window->speedPlot()->axisText().startsWith(QStringLiteral("mm/min")));
        QVERIFY(label(m_window->statusPanel(), "statusFeed").endsWith(QStringLiteral(" mm/min")));
    }
};

QTEST_MAIN(WorkflowUnitsTest)
#include "workflow_units_test.moc"
