// trace_replay: the regression helper of serial traces (tracedrive.h, docs/serial-trace.md).
//   trace_replay TRACE             replay TRACE against the driver; exit 1 with the trace line
//   trace_replay --record RECIPE   drive RECIPE's operation on the emulator, write the record
//                                  over RECIPE (its header kept)
//   trace_replay --roundtrip TRACE record TRACE's operation on the emulator now, replay that

#include "tracedrive.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

using namespace frezka;

namespace {

bool readTrace(const std::string &path, emulator::SerialTrace &trace)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "%s: cannot read\n", path.c_str());
        return false;
    }
    std::stringstream text;
    text << in.rdbuf();
    emulator::TraceMessage error;
    if (!emulator::parseTrace(text.str(), trace, error)) {
        std::fprintf(stderr, "%s:%d: %s\n", path.c_str(), error.line,
                     emulator::englishText(error).c_str());
        return false;
    }
    return true;
}

std::string dirOf(const std::string &path)
{
    const auto slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

} // namespace

int main(int argc, char **argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: trace_replay [--record | --roundtrip] TRACE\n");
        return 2;
    }
    const std::string mode = argc > 2 ? argv[1] : "";
    const std::string path = argv[argc - 1];
    emulator::SerialTrace trace;
    if (!readTrace(path, trace))
        return 2;
    std::string error;
    if (mode == "--record" || mode == "--roundtrip") {
        emulator::SerialTrace recorded;
        if (!driver::tracetest::recordTrace(trace, dirOf(path), recorded, error)) {
            std::fprintf(stderr, "%s: recording failed: %s\n", path.c_str(), error.c_str());
            return 1;
        }
        const std::string text = emulator::formatTrace(recorded);
        if (mode == "--record") {
            std::ofstream(path, std::ios::binary) << text;
            std::printf("%s: %zu entries recorded\n", path.c_str(), recorded.entries.size());
            return 0;
        }
        emulator::TraceMessage parseError;
        if (!emulator::parseTrace(text, trace, parseError)) {
            std::fprintf(stderr, "the fresh record does not read back: line %d: %s\n",
                         parseError.line, emulator::englishText(parseError).c_str());
            return 1;
        }
    }
    if (!driver::tracetest::replayTrace(trace, dirOf(path), error)) {
        std::fprintf(stderr, "%s: FAILED: %s\n", path.c_str(), error.c_str());
        return 1;
    }
    std::printf("%s: the driver did what the trace recorded (%zu entries)\n", path.c_str(),
                trace.entries.size());
    return 0;
}
