#pragma once
// What the frezka-cli process tests share: run the CLI as a child process and read what it said,
// write an input file into the test's temporary folder, and take the JSON report a command
// prints as its last line.

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStringList>
#include <QTemporaryDir>

namespace clitest {

struct Run
{
    int code = -1;
    QString out;
    QString err;
};

// Runs `program` with `args`; standard input closed at once unless `closeInput` is false (the
// CLI then sees no terminal and no end of input). Waits up to `timeoutMs`.
inline Run runCli(const QString &program, const QStringList &args, bool closeInput = true,
                  int timeoutMs = 120000)
{
    QProcess p;
    p.start(program, args);
    if (closeInput)
        p.closeWriteChannel();
    p.waitForFinished(timeoutMs);
    return {p.exitCode(), QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}

inline QString writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &text)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    f.open(QIODevice::WriteOnly);
    f.write(text);
    return path;
}

// The JSON object on the last line of a command's output (run's report, plan's summary).
inline QJsonObject lastJson(const QString &out)
{
    const QStringList lines = out.trimmed().split(QLatin1Char('\n'));
    return QJsonDocument::fromJson(lines.last().toUtf8()).object();
}

} // namespace clitest
