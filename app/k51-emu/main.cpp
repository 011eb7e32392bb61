// k51-emu: an ANC/K51 grinding control on a pseudo-terminal, for tests and for trying the
// transfer tools without a machine. Prints the terminal path on the first line of stdout.
#include "app/common/version.h"
#include "app/k51-emu/options.h"
#include "app/k51-emu/ptyserver.h"
#include "driver/grinder/family.h"

#include <csignal>
#include <cstdio>
#include <string>

namespace {
volatile std::sig_atomic_t g_stop = 0;
void onSignal(int)
{
    g_stop = 1;
}
} // namespace

int main(int argc, char *argv[])
{
    using namespace frezka::k51emu;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--version") {
            std::printf("k51-emu %s\n", frezka::app::versionString());
            return 0;
        }
    }
    Options options;
    std::string error;
    if (!parseOptions(std::vector<std::string>(argv + 1, argv + argc), options, error)) {
        std::fprintf(stderr, "k51-emu: %s\n", error.c_str());
        return 2;
    }
    if (options.help) {
        std::fputs(usageText().c_str(), stdout);
        return 0;
    }
    if (!options.note.empty())
        std::fprintf(stderr, "k51-emu: %s\n", options.note.c_str());
    struct sigaction action
    {
    };
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    std::signal(SIGPIPE, SIG_IGN);

    const int baud = options.baud > 0
                         ? options.baud
                         : frezka::grinder::familyInfo(options.config.family).defaultBaud;
    PtyServer server(options.config, baud, options.fast, options.baud > 0);
    const std::string path = server.open(error);
    if (path.empty()) {
        std::fprintf(stderr, "k51-emu: %s\n", error.c_str());
        return 1;
    }
    std::printf("%s\n", path.c_str());
    std::fflush(stdout);
    return server.run(g_stop, options.verbose, options.storePath);
}
