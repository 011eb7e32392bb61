// Machine › Tool table › Measure length (issue 19 item 1) on the window's own link: a profile
// with a tool length sensor, the built-in emulator in real time whose simulated sensor top
// (FREZKA_EMULATOR_SURFACE) is where the tool trips. The selected tool is probed fast then slow
// through the driver's controller; its length (trip minus the reference) lands in its row and
// in the table file, the other rows and words kept; the unit ends over the sensor at its
// clearance. Closing the table while measuring stops the probe and raises the tool.

#include "gui/mainwindow.h"
#include "gui/tooltabledialog.h"

#include "windowtest.h"

#include "driver/link/machinecontroller.h"
#include "machine/machineconfig.h"

#include <QFile>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace frezka;
using namespace frezka::gui;
using driver::MachineMode;

class ToolTableMeasureTest : public QObject
{
    Q_OBJECT

    const driver::MachineState &state() const { return m_window->controller()->state(); }

private slots:
    void initTestCase()
    {
        // Tool 2 trips 7.25 mm above the reference tool's -30.
        QVERIFY(m_dir.isValid());
        machine::MachineConfig profile = machine::defaultMachineConfig(protocol::Variant::Gve64);
        profile.link.port = "emulator";
        machine::ToolSensorConfig &s = profile.tools.sensor;
        s.enabled = true;
        s.xMm = 380;
        s.yMm = 10;
        s.clearanceZMm = -2;
        s.travelMm = 40;
        s.feedMmPerMin = 400;
        s.slowFeedMmPerMin = 40;
        s.retractMm = 1;
        s.referenceZMm = -30;
        QFile table(m_dir.filePath(QStringLiteral("tool.tbl")));
        QVERIFY(table.open(QIODevice::WriteOnly));
        table.write("T1 P1 Z0 D6 ;reference\nT2 P2 Z1 D2 ;engraver\n");
        table.close();
        m_window = gui::test::emulatorWindow(m_dir, "plane:-22.75,0,0",
                                             QStringLiteral("FrezkaToolMeasureTest"), &profile);
        QVERIFY(m_window);
    }

    void measuresTheSelectedToolIntoTheTable()
    {
        ToolTableDialog *dlg = m_window->openToolTable();
        QVERIFY(dlg);
        QPushButton *measure = test::button(dlg, "measureTool");
        QVERIFY(measure->isVisible());
        dlg->grid()->setCurrentCell(1, ToolTableDialog::LengthColumn);
        QSignalSpy measured(dlg, &ToolTableDialog::measured);
        measure->click();
        QVERIFY2(dlg->measuring(), qPrintable(dlg->errorText()));
        QTRY_VERIFY_WITH_TIMEOUT(!dlg->measuring(), 60000);
        QVERIFY2(dlg->errorText().isEmpty(), qPrintable(dlg->errorText()));
        QCOMPARE(measured.size(), 1);
        QCOMPARE(measured.front()[0].toInt(), 2);
        const double length = measured.front()[1].toDouble();
        QVERIFY2(std::abs(length - 7.25) <= 1.0 / 200, qPrintable(QString::number(length)));
        QCOMPARE(dlg->grid()->item(1, ToolTableDialog::LengthColumn)->text().toDouble(), length);
        QFile f(m_dir.filePath(QStringLiteral("tool.tbl")));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        QVERIFY2(text.startsWith("T1 P1 D6 ;reference\nT2 P2 Z7.25 D2 ;engraver"),
                 text.constData());
        // Over the sensor at its clearance, on the unit's counters.
        QTRY_VERIFY(state().mode == MachineMode::Idle);
        QCOMPARE(state().positionSteps[0], 380 * 200);
        QCOMPARE(state().positionSteps[1], 10 * 200);
        QCOMPARE(state().positionSteps[2], -2 * 200);
    }

    // Close pressed while the tool goes down: the probe stops, the tool goes back up to the
    // clearance, the table stays open and unchanged.
    void closingWhileMeasuringRaisesTheTool()
    {
        ToolTableDialog *dlg = m_window->openToolTable();
        dlg->grid()->setCurrentCell(0, ToolTableDialog::ToolColumn);
        test::button(dlg, "measureTool")->click();
        QVERIFY(dlg->measuring());
        QTRY_VERIFY_WITH_TIMEOUT(state().positionSteps[2] < -4 * 200, 30000);
        dlg->close();
        QVERIFY(dlg->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(!dlg->measuring(), 60000);
        QTRY_VERIFY_WITH_TIMEOUT(
            state().mode == MachineMode::Idle && state().positionSteps[2] == -2 * 200, 30000);
        QVERIFY(!dlg->errorText().isEmpty());
        QFile f(m_dir.filePath(QStringLiteral("tool.tbl")));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readAll().startsWith("T1 P1 D6 ;reference\n"));
        dlg->close();
        QVERIFY(!dlg->isVisible());
    }

    void cleanupTestCase() { m_window.reset(); }

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
};

QTEST_MAIN(ToolTableMeasureTest)
#include "tooltable_measure_test.moc"
