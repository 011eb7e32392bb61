// frezka-cli check on a program that never ends (issue 17 item 4), run as a process: an o-word
// loop that moves, one that does not, and a recursion each exit 1 with the line of the loop (or
// the recursive call) named as FILE:LINE:COL, the bound it reached and the line the program had
// got to, and the process's peak memory (the children's largest resident set, getrusage) stays
// under 800 MB. The loop that moves runs to the default bound; the others to a profile's bound
// (program.maxLinesExecuted, program.maxMoves), which --machine brings.

#include "cliprocess.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <sys/resource.h>

class CliEndlessTest : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    struct Run
    {
        int code = -1;
        QString err;
        double peakMb = 0; // the largest resident set of the children waited for so far
    };

    QString write(const QString &name, const QByteArray &text)
    {
        return clitest::writeFile(m_dir, name, text);
    }

    static Run check(const QStringList &args)
    {
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C.UTF-8"));
        env.insert(QStringLiteral("LANG"), QStringLiteral("C.UTF-8"));
        env.remove(QStringLiteral("LANGUAGE"));
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(FREZKA_CLI), QStringList{QStringLiteral("check")} + args);
        p.closeWriteChannel();
        p.waitForFinished(600000);
        rusage usage{};
        getrusage(RUSAGE_CHILDREN, &usage);
        return {p.exitCode(), QString::fromUtf8(p.readAllStandardError()),
                double(usage.ru_maxrss) / 1024.0};
    }

    // The shipped GVE64 profile with these bounds.
    QString profile(int maxLinesExecuted, int maxMoves)
    {
        QFile shipped(QStringLiteral(FREZKA_SOURCE_DIR "/resources/machines/gve64.json"));
        if (!shipped.open(QIODevice::ReadOnly))
            return {};
        QJsonObject json = QJsonDocument::fromJson(shipped.readAll()).object();
        json[QStringLiteral("program")] =
            QJsonObject{{QStringLiteral("maxLinesExecuted"), maxLinesExecuted},
                        {QStringLiteral("maxMoves"), maxMoves}};
        return write(QStringLiteral("bounded.json"), QJsonDocument(json).toJson());
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void aLoopThatMovesStopsAtTheDefaultBound()
    {
        const QString file = write(QStringLiteral("endless-moves.nc"), "G21 G90 F1000\n"
                                                                       "o1 while [1]\n"
                                                                       "G1 X10\n"
                                                                       "G1 X0\n"
                                                                       "o1 endwhile\n"
                                                                       "M2\n");
        const Run r = check({file});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.startsWith(file + QStringLiteral(":2:1: o1 while has not ended after "
                                                        "10000000 moves (it was stopped at "
                                                        "line 3). Check what ends it")),
                 qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("program.maxMoves")), qPrintable(r.err));
        QVERIFY2(r.peakMb > 10 && r.peakMb < 800, qPrintable(QString::number(r.peakMb)));
    }

    void aLoopWithoutMotionStopsAtTheProfilesBound()
    {
        const QString file = write(QStringLiteral("endless-spin.nc"), "#1 = 0\n"
                                                                      "o<spin> do\n"
                                                                      "#1 = [#1 + 1]\n"
                                                                      "o<spin> while [#1 gt 0]\n"
                                                                      "M2\n");
        const QString machine = profile(2'000'000, 10'000'000);
        QVERIFY(!machine.isEmpty());
        const Run r = check({file, QStringLiteral("--machine"), machine});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.startsWith(file + QStringLiteral(":2:1: o<spin> do has not ended after "
                                                        "2000000 lines executed")),
                 qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("program.maxLinesExecuted")), qPrintable(r.err));
        QVERIFY2(r.peakMb < 800, qPrintable(QString::number(r.peakMb)));
    }

    void aRecursionThatMovesNamesItsRecursiveCall()
    {
        const QString file = write(QStringLiteral("endless-tree.nc"), "G21 G90 F1000\n"
                                                                      "o<tree> sub\n"
                                                                      "G1 X[#1]\n"
                                                                      "o10 if [#1 lt 60]\n"
                                                                      "  o<tree> call [#1 + 1]\n"
                                                                      "  o<tree> call [#1 + 1]\n"
                                                                      "o10 endif\n"
                                                                      "o<tree> endsub\n"
                                                                      "o<tree> call [0]\n"
                                                                      "M2\n");
        const Run r = check({file, QStringLiteral("--machine"), profile(100'000'000, 500'000)});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.startsWith(file + QStringLiteral(":5:3: o<tree> call has not ended after "
                                                        "500000 moves")),
                 qPrintable(r.err));
        QVERIFY2(r.peakMb < 800, qPrintable(QString::number(r.peakMb)));
    }
};

QTEST_GUILESS_MAIN(CliEndlessTest)
#include "cli_endless_test.moc"
