// Machine › Probe work zero (issue 19 item 2) on the window's own link: the built-in emulator
// in real time with a work block (FREZKA_EMULATOR_SURFACE block:..., the tool's radius added
// on each side, as the emulator's probe is the tool's centre). Each guided step has its picture
// (drawn, the work's colour in it); an X edge and an outside corner set the active work
// system's X / Y with the tool's radius taken into account, the unit's counters back where the
// tool started; a probe that never touches sets nothing and says why.

#include "gui/mainwindow.h"
#include "gui/probesetuppicture.h"
#include "gui/probezerodialog.h"

#include "windowtest.h"

#include "driver/link/machinecontroller.h"
#include "session/workoffsets.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace frezka;
using namespace frezka::gui;
using driver::MachineMode;

class ProbeZeroTest : public QObject
{
    Q_OBJECT

    const driver::MachineState &state() const { return m_window->controller()->state(); }

    static void value(ProbeZeroDialog *d, const char *name, double v)
    {
        d->findChild<QDoubleSpinBox *>(QLatin1String(name))->setValue(v);
    }

    bool probeAndWait(ProbeZeroDialog *d)
    {
        test::button(d, "probe")->click();
        if (!d->isProbing())
            return false;
        return QTest::qWaitFor([d] { return !d->isProbing(); }, 60000);
    }

private slots:
    void initTestCase()
    {
        // The work: X 10..90, Y 8..90 for a 4 mm tool (its centre touches 2 mm before a side).
        QVERIFY(m_dir.isValid());
        m_window = gui::test::emulatorWindow(m_dir, "block:8,6,92,92,5",
                                             QStringLiteral("FrezkaProbeZeroTest"));
        QVERIFY(m_window);
        m_window->offsets()->setSystem(0, {1, 2, 3, 0});
        m_window->selectWorkOffset(0);
    }

    void eachStepHasItsPicture()
    {
        ProbeZeroDialog *d = m_window->openProbeZero();
        QVERIFY(d && d->isVisible());
        for (int k = 0; k < 5; ++k) {
            d->setKind(static_cast<ProbeZeroDialog::Kind>(k));
            QCOMPARE(int(d->picture()->kind()), k);
            const QImage image = d->picture()->grab().toImage();
            int work = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x)
                    work += image.pixelColor(x, y) == QColor(176, 141, 87);
            QVERIFY2(work > image.width() * image.height() / 20, qPrintable(QString::number(k)));
            if (const QString dir = qEnvironmentVariable("FREZKA_TEST_SHOTS"); !dir.isEmpty())
                d->grab().save(QStringLiteral("%1/probezero-%2.png").arg(dir).arg(k));
        }
        QVERIFY(!d->findChild<QDoubleSpinBox *>(QStringLiteral("plate"))->isVisible());
        d->setKind(ProbeZeroDialog::ZPlate);
        QVERIFY(d->findChild<QDoubleSpinBox *>(QStringLiteral("plate"))->isVisible());
    }

    // The tool jogged beside the X face first (Y 30), then back to Y 0.
    void anXEdgeSetsTheActiveSystemsX()
    {
        m_window->controller()->jogStep(1, 30, 1000);
        QTRY_VERIFY_WITH_TIMEOUT(
            state().mode == MachineMode::Idle && state().positionSteps[1] == 30 * 200, 30000);
        ProbeZeroDialog *d = m_window->openProbeZero();
        d->setKind(ProbeZeroDialog::XEdge);
        d->findChild<QComboBox *>(QStringLiteral("xDirection"))->setCurrentIndex(0); // +
        value(d, "toolDiameter", 4);
        value(d, "travel", 20);
        value(d, "probeFeed", 300);
        QVERIFY2(probeAndWait(d), qPrintable(d->errorText()));
        QVERIFY2(d->errorText().isEmpty(), qPrintable(d->errorText()));
        const session::Axes4 g54 = m_window->offsets()->systems()[0];
        QVERIFY2(std::abs(g54[0] - 10) <= 1.0 / 200, qPrintable(QString::number(g54[0])));
        QCOMPARE(g54[1], 2.0);
        QCOMPARE(g54[2], 3.0);
        QTRY_VERIFY(state().mode == MachineMode::Idle);
        QCOMPARE(state().positionSteps[0], 0);
        QCOMPARE(state().positionSteps[1], 30 * 200);
        m_window->controller()->jogStep(1, -30, 1000);
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Idle && state().positionSteps[1] == 0,
                                 30000);
    }

    void anOutsideCornerSetsXAndY()
    {
        ProbeZeroDialog *d = m_window->openProbeZero();
        d->setKind(ProbeZeroDialog::OutsideCorner);
        d->findChild<QComboBox *>(QStringLiteral("yDirection"))->setCurrentIndex(0); // +
        value(d, "reach", 15);
        QVERIFY2(probeAndWait(d), qPrintable(d->errorText()));
        const session::Axes4 g54 = m_window->offsets()->systems()[0];
        QVERIFY2(std::abs(g54[0] - 10) <= 1.0 / 200 && std::abs(g54[1] - 8) <= 1.0 / 200,
                 qPrintable(d->statusText()));
        QVERIFY2(d->statusText().contains(QStringLiteral("G54")), qPrintable(d->statusText()));
        QTRY_VERIFY(state().mode == MachineMode::Idle);
        QCOMPARE(state().positionSteps[0], 0);
        QCOMPARE(state().positionSteps[1], 0);
    }

    // An inside-corner probe from (0, 0): Y passes beside the block within its travel.
    void aProbeThatNeverTouchesSetsNothing()
    {
        ProbeZeroDialog *d = m_window->openProbeZero();
        d->setKind(ProbeZeroDialog::YEdge);
        value(d, "travel", 5);
        const session::OffsetState before = m_window->offsets()->state();
        QVERIFY(probeAndWait(d));
        QVERIFY2(d->errorText().contains(QStringLiteral("without touching the edge")),
                 qPrintable(d->errorText()));
        QVERIFY(m_window->offsets()->state() == before);
        QTRY_VERIFY(state().mode == MachineMode::Idle);
        QCOMPARE(state().positionSteps[1], 0);
        d->close();
        QVERIFY(!d->isVisible());
    }

    void cleanupTestCase() { m_window.reset(); }

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
};

QTEST_MAIN(ProbeZeroTest)
#include "probezero_test.moc"
