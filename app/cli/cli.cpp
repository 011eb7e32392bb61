#include "cli.h"

#include <cstdio>

namespace frezka::cli {

std::map<std::string, Command> &commands()
{
    static std::map<std::string, Command> table;
    return table;
}

bool registerCommand(const std::string &name, Command command)
{
    return commands().emplace(name, std::move(command)).second;
}

void out(const QString &text)
{
    const QByteArray bytes = text.toUtf8();
    std::fwrite(bytes.constData(), 1, static_cast<std::size_t>(bytes.size()), stdout);
    std::fflush(stdout);
}

void err(const QString &text)
{
    const QByteArray bytes = text.toUtf8();
    std::fwrite(bytes.constData(), 1, static_cast<std::size_t>(bytes.size()), stderr);
    std::fflush(stderr);
}

} // namespace frezka::cli
