#pragma once
// Test helpers: k51-emu as a child process on a pty, and frezka-cli runs.

#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

namespace frezka::grinder::test {

class EmuProcess
{
public:
    // Starts k51-emu with `args`; path() is the pty, or empty when it did not start.
    explicit EmuProcess(const QStringList &args);
    ~EmuProcess();
    QString path() const { return m_path; }
    // Sends SIGTERM and returns the exit code (-1 when it did not exit normally).
    int terminate();
    QString errorOutput();
    QProcess &process() { return m_process; }

private:
    QProcess m_process;
    QString m_path;
};

struct CliRun
{
    int exitCode = -1;
    QString out;
    QString err;
};
CliRun runCli(const QStringList &args, int timeoutMs = 60000);

QByteArray readAll(const QString &path);
bool writeAll(const QString &path, const QByteArray &data);

} // namespace frezka::grinder::test
