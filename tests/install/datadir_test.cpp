// The shipped-data lookup (app/common/datadir.h) both ways, and the serial permission message
// of both serial transports (issue 18 items 1 and 5).
#include "app/common/datadir.h"
#include "driver/grinder/transport.h"
#include "driver/link/serialtransport.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <grp.h>
#include <unistd.h>

class DataDirTest : public QObject
{
    Q_OBJECT

private slots:
    void installedLayoutIsFoundBesideBin()
    {
        QTemporaryDir prefix;
        QVERIFY(prefix.isValid());
        QVERIFY(QDir(prefix.path()).mkpath(QStringLiteral("bin")));
        QVERIFY(QDir(prefix.path()).mkpath(QStringLiteral("share/frezka/machines")));
        QCOMPARE(frezka::app::dataDirFor(prefix.path() + QStringLiteral("/bin")),
                 prefix.path() + QStringLiteral("/share/frezka"));
    }

    void buildTreeFallsBackToTheSourceResources()
    {
        QTemporaryDir buildApp; // no share/frezka beside it
        QVERIFY(buildApp.isValid());
        QCOMPARE(frezka::app::dataDirFor(buildApp.path()), QStringLiteral(FREZKA_SOURCE_DATA_DIR));
        QVERIFY(QFile::exists(frezka::app::dataDirFor(buildApp.path()) +
                              QStringLiteral("/machines/gve84.json")));
    }

    void shippedProfileByName()
    {
        // This test runs from the build tree: the names resolve into the source resources.
        const QString expected = QStringLiteral(FREZKA_SOURCE_DATA_DIR "/machines/gve84.json");
        QCOMPARE(frezka::app::resolveProfile(QStringLiteral("gve84")), expected);
        QCOMPARE(frezka::app::resolveProfile(QStringLiteral("gve84.json")), expected);
        QCOMPARE(frezka::app::resolveProfile(QStringLiteral("nosuch")), QStringLiteral("nosuch"));
        QCOMPARE(frezka::app::resolveProfile(QStringLiteral("./gve84")), QStringLiteral("./gve84"));
    }

    void permissionDeniedNamesTheGroupAndTheCommand()
    {
        QTemporaryDir dir;
        const QString port = dir.path() + QStringLiteral("/ttyUSB0");
        QFile f(port);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.close();
        QString owner = QStringLiteral("dialout");
        if (const struct group *g = ::getgrnam("uucp");
            g && ::getuid() == 0 &&
            ::chown(QFile::encodeName(port).constData(), gid_t(-1), g->gr_gid) == 0)
            owner = QStringLiteral("uucp"); // a device owned by another group: named as it is
        const QString command = QStringLiteral("sudo usermod -aG %1 $USER").arg(owner);
        const QString link = frezka::driver::serialOpenFailure(port, QSerialPort::PermissionError,
                                                               QStringLiteral("Permission denied"));
        QVERIFY2(link.contains(port) && link.contains(command), qPrintable(link));
        QVERIFY2(link.contains(QStringLiteral("log out and in again")), qPrintable(link));
        const QString grinder =
            frezka::grinder::serialOpenFailure(port, true, QStringLiteral("Permission denied"));
        QVERIFY2(grinder.contains(port) && grinder.contains(command), qPrintable(grinder));
    }

    void otherErrorsKeepQtsWords()
    {
        const QString link = frezka::driver::serialOpenFailure(
            QStringLiteral("/dev/ttyS7"), QSerialPort::DeviceNotFoundError,
            QStringLiteral("No such file or directory"));
        QCOMPARE(link, QStringLiteral("cannot open /dev/ttyS7: No such file or directory"));
        QVERIFY(!link.contains(QStringLiteral("usermod")));
        const QString grinder = frezka::grinder::serialOpenFailure(
            QStringLiteral("/dev/ttyS7"), false, QStringLiteral("No such file or directory"));
        QVERIFY(!grinder.contains(QStringLiteral("usermod")));
    }
};

QTEST_GUILESS_MAIN(DataDirTest)
#include "datadir_test.moc"
