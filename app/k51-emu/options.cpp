#include "app/k51-emu/options.h"

#include "driver/grinder/zposition.h"

#include <charconv>
#include <fstream>
#include <iterator>

namespace frezka::k51emu {

using namespace frezka::grinder;

std::string usageText()
{
    return R"(usage: k51-emu [OPTIONS]

Emulates an ANC/K51 grinding control on a pseudo-terminal. The first line printed on stdout is
the terminal's path (e.g. /dev/pts/5); open it like a serial port. Runs until SIGINT/SIGTERM.

Controller:
  --family anc|k51|hedit  message family (default k51): anc = ANCLOAD/ANCSAVE (no header,
                          1-byte checksum), k51 = K51LOAD/K51SAVE/KCOMM, hedit = HEDIT data
  --image FILE            data the controller holds (default: a generated image of 0x5506,
                          0x5507 or 0x2E bytes with valid inner blocks)
  --header TEXT           16-character header sent with the data (default "FREZKA EMU")
  --konfig6 N             transfer mode, K51-1 numbering: 0 none (silent), 1 Z-position,
                          2 programs (default), 3 table
  --k51-2                 read --konfig6 with K51-2 numbering: 0 none, 1 programs
  --zform 1|2             Z-position protocol: 1 ASCII both ways (default), 2 binary one way
  --z-start MM            initial Z position in mm (default -1.234)
  --z-speed MM_PER_S      table speed for GO (default 20)
  --store FILE            after every accepted load write the received data to FILE

Line:
  --baud N                pace every byte at 10 bits / N s (default 9600)
  --fast                  no pacing (for tests)
  --reply-delay-ms N      controller's pause before each answer (default 2)

Faults:
  --naks N                answer the first N good data messages with NAK
  --corrupt N             corrupt one byte of the first N data messages sent
  --noise                 send noise bytes before every answer
  --silent                never answer
  --silent-after N        stop answering after N answers

Other:
  --verbose               trace every message on stderr
  --help                  this text
)";
}

namespace {

bool toInt(const std::string &text, long long &value)
{
    const char *end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end;
}

bool readFile(const std::string &path, Bytes &bytes)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return false;
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return true;
}

} // namespace

bool parseOptions(const std::vector<std::string> &args, Options &options, std::string &error)
{
    EmulatorConfig &c = options.config;
    int konfig6 = 2;
    bool k51Type2 = false;
    std::string imagePath;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string &arg = args[i];
        auto value = [&](std::string &out) {
            if (i + 1 >= args.size()) {
                error = arg + " needs a value";
                return false;
            }
            out = args[++i];
            return true;
        };
        auto number = [&](long long &out, long long lo, long long hi) {
            std::string text;
            if (!value(text))
                return false;
            if (!toInt(text, out) || out < lo || out > hi) {
                error = arg + ": '" + text + "' is not a number from " + std::to_string(lo) +
                        " to " + std::to_string(hi);
                return false;
            }
            return true;
        };
        auto millimetres = [&](std::int64_t &out) {
            std::string text;
            if (!value(text))
                return false;
            const auto um = parseMillimetres(text);
            if (!um) {
                error = arg + ": '" + text + "' is not a length in mm (e.g. -1.234)";
                return false;
            }
            out = *um;
            return true;
        };
        long long n = 0;
        std::string text;
        if (arg == "--help" || arg == "-h") {
            options.help = true;
        } else if (arg == "--family") {
            if (!value(text))
                return false;
            const auto family = familyFromId(text);
            if (!family) {
                error = "--family: '" + text + "' is not anc, k51 or hedit";
                return false;
            }
            c.family = *family;
        } else if (arg == "--image") {
            if (!value(imagePath))
                return false;
        } else if (arg == "--header") {
            if (!value(text))
                return false;
            c.header = headerFromText(text);
        } else if (arg == "--konfig6") {
            if (!number(n, 0, 255))
                return false;
            konfig6 = int(n);
        } else if (arg == "--k51-2") {
            k51Type2 = true;
        } else if (arg == "--zform") {
            if (!number(n, 1, 2))
                return false;
            c.zForm = int(n);
        } else if (arg == "--z-start") {
            if (!millimetres(c.zStartUm))
                return false;
        } else if (arg == "--z-speed") {
            std::int64_t umPerS = 0;
            if (!millimetres(umPerS))
                return false;
            if (umPerS <= 0) {
                error = "--z-speed must be positive";
                return false;
            }
            c.zSpeedUmPerS = umPerS;
        } else if (arg == "--store") {
            if (!value(options.storePath))
                return false;
        } else if (arg == "--baud") {
            if (!number(n, 50, 4000000))
                return false;
            options.baud = int(n);
        } else if (arg == "--fast") {
            options.fast = true;
        } else if (arg == "--reply-delay-ms") {
            if (!number(n, 0, 600000))
                return false;
            c.replyDelayUs = n * 1000;
        } else if (arg == "--naks") {
            if (!number(n, 0, 1000000))
                return false;
            c.nakCount = int(n);
        } else if (arg == "--corrupt") {
            if (!number(n, 0, 1000000))
                return false;
            c.corruptCount = int(n);
        } else if (arg == "--noise") {
            c.noise = true;
        } else if (arg == "--silent") {
            c.silentAfterReplies = 0;
        } else if (arg == "--silent-after") {
            if (!number(n, 0, 1000000))
                return false;
            c.silentAfterReplies = int(n);
        } else if (arg == "--verbose") {
            options.verbose = true;
        } else {
            error = "unknown option '" + arg + "' (see --help)";
            return false;
        }
    }
    const auto mode = transferModeFromKonfig6(konfig6, k51Type2);
    if (!mode) {
        error = "--konfig6 " + std::to_string(konfig6) + " is not a transfer mode of " +
                (k51Type2 ? "K51-2 (0 or 1)" : "K51-1 (0 to 3)");
        return false;
    }
    c.mode = *mode;
    if (!imagePath.empty()) {
        if (!readFile(imagePath, c.image)) {
            error = "--image: cannot read '" + imagePath + "'";
            return false;
        }
        if (c.image.empty() || c.image.size() + kHeaderSize > kMaxPayload) {
            error = "--image: '" + imagePath + "' has " + std::to_string(c.image.size()) +
                    " bytes; a message carries 1 to 65519";
            return false;
        }
    }
    return true;
}

} // namespace frezka::k51emu
