// Machine › Height map on the window's own link (issue 19): the built-in emulator in real time
// with the work top of FREZKA_EMULATOR_SURFACE, probed from the dialog through the driver's
// controller in its thread; the heights are the plane's and the tool ends at the clearance.

#include "gui/heightmapdialog.h"
#include "gui/mainwindow.h"

#include "windowtest.h"

#include "driver/link/machinecontroller.h"

#include <QDoubleSpinBox>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace frezka;
using namespace frezka::gui;
using driver::MachineMode;

class HeightMapLiveTest : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_window = gui::test::emulatorWindow(m_dir, "plane:-5,0.01,0.005",
                                             QStringLiteral("FrezkaHeightMapLiveTest"));
        QVERIFY(m_window);
    }

    void probesTheBuiltInEmulatorsSurface()
    {
        m_window->offsets()->setSystem(0, {10, 10, -5, 0});
        m_window->selectWorkOffset(0);
        HeightMapDialog *dialog = m_window->openHeightMap();
        auto value = [dialog](const char *name, double v) {
            dialog->findChild<QDoubleSpinBox *>(QLatin1String(name))->setValue(v);
        };
        value("areaX0", 0);
        value("areaY0", 0);
        value("areaX1", 10);
        value("areaY1", 10);
        value("spacing", 10);
        value("clearance", 1);
        value("depth", 2);
        value("probeFeed", 300);
        QTRY_VERIFY(test::button(dialog, "probe")->isEnabled());
        test::button(dialog, "probe")->click();
        QVERIFY2(dialog->isProbing(), qPrintable(dialog->errorText()));
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isProbing(), 60000);
        QVERIFY2(dialog->map().has_value(), qPrintable(dialog->errorText()));
        const gcode::HeightMap &map = *dialog->map();
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                QVERIFY2(std::abs(map.z(i, j) - (0.1 * i + 0.05 * j)) <= 1.0 / 200 + 1e-9,
                         qPrintable(QString::number(map.z(i, j))));
        QTRY_COMPARE(m_window->controller()->state().positionSteps[2], -4 * 200);
        QVERIFY(dialog->statusText().contains(QStringLiteral("4")));
    }

    void cleanupTestCase() { m_window.reset(); }

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
};

QTEST_MAIN(HeightMapLiveTest)
#include "heightmap_live_test.moc"
