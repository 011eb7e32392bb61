// frezka-cli: the headless front end (check, toolpath, plan, run, grinder, ...).
#include "cli.h"

#include "app/common/translator.h"

#include <QCoreApplication>

using namespace frezka::cli;

namespace {

void printUsage()
{
    QString text = QStringLiteral("usage: frezka-cli COMMAND [ARGS...]\n\ncommands:\n");
    for (const auto &[name, command] : commands()) {
        text += QStringLiteral("  %1\n      %2\n")
                    .arg(QString::fromStdString(command.usage),
                         QString::fromStdString(command.summary));
    }
    err(text);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("frezka-cli"));
    QCoreApplication::setOrganizationName(QStringLiteral("Frezka"));
    frezka::app::installTranslator();
    QStringList args = app.arguments().mid(1);
    if (args.isEmpty() || args.first() == QLatin1String("--help") ||
        args.first() == QLatin1String("-h")) {
        printUsage();
        return args.isEmpty() ? 2 : 0;
    }
    const std::string name = args.takeFirst().toStdString();
    const auto it = commands().find(name);
    if (it == commands().end()) {
        err(QStringLiteral("frezka-cli: unknown command '%1'\n").arg(QString::fromStdString(name)));
        printUsage();
        return 2;
    }
    return it->second.run(args);
}
