// Small widgets: program text index, console (hex, save), jog semantics, run panel phases,
// speed-plot decimation, DRO axes.
#include "gui/consolewidget.h"
#include "gui/drowidget.h"
#include "gui/holdbanner.h"
#include "gui/jogpanel.h"
#include "gui/programview.h"
#include "gui/runpanel.h"
#include "gui/speedplot.h"

#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>

using namespace frezka::gui;

class WidgetsTest : public QObject
{
    Q_OBJECT

private slots:
    void programTextIndexesLines()
    {
        const ProgramText t(QByteArray("G0 X1\r\nG1 Y2\n\nM30"));
        QCOMPARE(t.lineCount(), 4);
        QCOMPARE(t.line(0), QStringLiteral("G0 X1"));
        QCOMPARE(t.line(1), QStringLiteral("G1 Y2"));
        QCOMPARE(t.line(2), QString());
        QCOMPARE(t.line(3), QStringLiteral("M30"));
        QCOMPARE(ProgramText(QByteArray("A\n")).lineCount(), 1);
        QCOMPARE(ProgramText(QByteArray()).lineCount(), 0);
    }

    void consoleShowsHexAndSaves()
    {
        ConsoleWidget c;
        c.append(LogDirection::Sent, QByteArray("!0PF\r"));
        c.append(LogDirection::Received, QByteArray("0,1,2,3\r"));
        QVERIFY(c.formatEntry(c.entries()[0]).endsWith(QStringLiteral("> !0PF\\r")));
        c.setHex(true);
        QVERIFY(c.formatEntry(c.entries()[0]).endsWith(QStringLiteral("> 21 30 50 46 0D")));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("log.txt"));
        QVERIFY(c.saveTo(path));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().split('\n');
        QVERIFY(lines[0].endsWith("> 21 30 50 46 0D"));
        QVERIFY(lines[1].endsWith("< 30 2C 31 2C 32 2C 33 0D"));
        QString error;
        QVERIFY(!c.saveTo(dir.filePath(QStringLiteral("no/such/dir/log.txt")), &error));
        QVERIFY(!error.isEmpty());
    }

    void consoleHidesPollsUnlessAsked()
    {
        ConsoleWidget c;
        c.append(LogDirection::Sent, QByteArray("!0PF,A1"));
        c.append(LogDirection::Received, QByteArray("0,1,2,3,5C"));
        c.append(LogDirection::Sent, QByteArray("!0C10,0,0"));
        c.append(LogDirection::Received, QByteArray("0"));
        QVERIFY(c.entries()[0].poll && c.entries()[1].poll);
        QVERIFY(!c.entries()[2].poll && !c.entries()[3].poll);
        c.flush();
        auto *view = c.findChild<QPlainTextEdit *>(QStringLiteral("consoleLog"));
        QVERIFY(!view->toPlainText().contains(QStringLiteral("PF")));
        QVERIFY(view->toPlainText().contains(QStringLiteral("!0C10,0,0")));
        c.setShowPolls(true);
        QVERIFY(view->toPlainText().contains(QStringLiteral("!0PF")));
    }

    void consoleManualLine()
    {
        ConsoleWidget c;
        QSignalSpy spy(&c, &ConsoleWidget::manualLineEntered);
        auto *line = c.findChild<QLineEdit *>(QStringLiteral("consoleLine"));
        QVERIFY(line);
        line->setText(QStringLiteral("  !0PF "));
        emit line->returnPressed();
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toString(), QStringLiteral("!0PF"));
        QVERIFY(line->text().isEmpty());
    }

    void jogStepsAndContinuous()
    {
        JogPanel jog;
        QSignalSpy steps(&jog, &JogPanel::jogStepRequested);
        QSignalSpy starts(&jog, &JogPanel::jogContinuousStarted);
        QSignalSpy stops(&jog, &JogPanel::jogContinuousStopped);
        jog.setStepMm(0.1);
        QTest::mouseClick(jog.findChild<QPushButton *>(QStringLiteral("jogXMinus")),
                          Qt::LeftButton);
        QCOMPARE(steps.count(), 1);
        QCOMPARE(steps.at(0).at(0).toInt(), 0);
        QCOMPARE(steps.at(0).at(1).toDouble(), -0.1);
        jog.setStepMm(0);
        jog.jogKey(2, +1, true);
        jog.jogKey(2, +1, false);
        QCOMPARE(starts.count(), 1);
        QCOMPARE(starts.at(0).at(1).toInt(), 1);
        QCOMPARE(stops.count(), 1);
        jog.setAxisCount(3);
        jog.jogKey(3, 1, true); // no A on a 3-axis unit
        QCOMPARE(starts.count(), 1);
    }

    void runPanelPhases()
    {
        RunPanel p;
        auto *run = p.findChild<QPushButton *>(QStringLiteral("run"));
        auto *pause = p.findChild<QPushButton *>(QStringLiteral("pause"));
        auto *resume = p.findChild<QPushButton *>(QStringLiteral("resume"));
        p.setPhase(RunPhase::Ready, false);
        QVERIFY(!run->isEnabled());
        p.setPhase(RunPhase::Ready, true);
        QVERIFY(run->isEnabled());
        p.setPhase(RunPhase::Running, true);
        QVERIFY(!run->isEnabled() && pause->isEnabled() && !resume->isEnabled());
        p.setPhase(RunPhase::Paused, true);
        QVERIFY(resume->isEnabled() && !pause->isEnabled());
        QCOMPARE(RunPanel::formatDuration(3725), QStringLiteral("01:02:05"));
        QCOMPARE(RunPanel::formatDuration(-1), QStringLiteral("--:--:--"));
    }

    void speedDecimationKeepsDips()
    {
        std::vector<SpeedSample> v;
        for (int i = 0; i < 100000; ++i)
            v.push_back({double(i), i == 54321 ? 5.0 : 1000.0, std::uint32_t(i)});
        const auto d = decimateSpeed(v, 1000);
        QVERIFY(d.size() <= 1000);
        bool dip = false;
        for (const auto &s : d)
            dip = dip || s.speedMmPerMin == 5.0;
        QVERIFY(dip);
    }

    void droShowsAxesOfTheVariant()
    {
        DroWidget dro;
        dro.setAxisCount(3);
        dro.setPositions({1.5, -2, 3.25, 0}, {0.5, -1, 0.25, 0});
        QCOMPARE(dro.machineText(0), QStringLiteral("1.500"));
        QCOMPARE(dro.workText(2), QStringLiteral("0.250"));
        QVERIFY(dro.findChild<QWidget *>(QStringLiteral("droWorkA"))->isHidden());
    }

    // Off the planned path: the banner explains and offers Continue (which returns to the path)
    // and Abort, but not the KEEP tool lift (the unit holds no queue then).
    void holdBannerPathFault()
    {
        HoldBanner banner;
        QSignalSpy cont(&banner, &HoldBanner::continueRequested);
        banner.showHold(HoldBanner::Kind::PathFault, 42, QStringLiteral("driver text"));
        QVERIFY(!banner.isHidden());
        QVERIFY(banner.text().contains(QLatin1String("42")));
        QVERIFY(banner.text().contains(QLatin1String("path")));
        QStringList shown;
        for (QPushButton *b : banner.findChildren<QPushButton *>()) {
            if (!b->isHidden())
                shown << b->text();
        }
        QCOMPARE(shown.size(), 2);
        QVERIFY(shown.contains(QLatin1String("Continue")));
        QVERIFY(shown.contains(QLatin1String("Abort job")));
        for (QPushButton *b : banner.findChildren<QPushButton *>()) {
            if (b->text() == QLatin1String("Continue"))
                b->click();
        }
        QCOMPARE(cont.size(), 1);
        banner.showHold(HoldBanner::Kind::Paused, 42, {});
        int liftShown = 0;
        for (QPushButton *b : banner.findChildren<QPushButton *>())
            liftShown += !b->isHidden() && b->text() == QLatin1String("Lift tool") ? 1 : 0;
        QCOMPARE(liftShown, 1);
    }
};

QTEST_MAIN(WidgetsTest)
#include "widgets_test.moc"
