#include "app/k51-emu/options.h"

#include "driver/grinder/zposition.h"

#include <charconv>
#include <fstream>
#include <functional>
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
                          Any other --konfig6 value (an unprogrammed EEPROM byte, usually
                          255 = FF) is replaced at power-on by the firmware default
  --see-konfig6 N         that firmware default (SEE_KONFIG6 in KONFIG.A51; default 2 for
                          K51-1, 1 for K51-2)
  --selector pgn|other    the controller's selector (default pgn); FORM=1 answers only in PGN
  --zform 1|2             Z-position protocol: 1 ASCII both ways (default), 2 binary one way
  --z-start MM            initial Z position in mm (default -1.234)
  --z-speed MM_PER_S      table speed for GO (default 20)
  --store FILE            after every accepted load write the received data to FILE

Line:
  --baud N                the controller's rate: every byte each way takes 10 bits / N s
                          (default: the family's rate, ANC 4800, K51 and HEDIT 9600). Given
                          explicitly, a PC port set to another rate garbles every byte both
                          ways, as a baud rate mismatch on a real line does
  --fast                  no pacing either way (for tests)
  --reply-delay-ms N      controller's pause before each answer (default 2)

Faults:
  --naks N                answer the first N good data messages with NAK
  --corrupt N             corrupt one byte of the first N data messages sent
  --noise                 send noise bytes before every answer
  --silent                never answer
  --silent-after N        stop answering after N answers

Other:
  --verbose               trace every message, and every 1024 bytes received, on stderr
  --help                  this text
  --version               the version
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

// Parsing state beyond Options: values checked together at the end.
struct Pending
{
    int konfig6 = 2;
    int seeKonfig6 = -1; // -1: 2 for K51-1, 1 for K51-2
    bool k51Type2 = false;
    std::string imagePath;
};

bool parseNumber(const std::string &option, const std::string &text, long long lo, long long hi,
                 long long &out, std::string &error)
{
    if (toInt(text, out) && out >= lo && out <= hi)
        return true;
    error = option + ": '" + text + "' is not a number from " + std::to_string(lo) + " to " +
            std::to_string(hi);
    return false;
}

bool parseLength(const std::string &option, const std::string &text, std::int64_t &um,
                 std::string &error)
{
    const auto value = parseMillimetres(text);
    if (!value) {
        error = option + ": '" + text + "' is not a length in mm (e.g. -1.234)";
        return false;
    }
    um = *value;
    return true;
}

// Options without a value; false when `option` is not one of them.
bool parseFlag(const std::string &option, Options &options, Pending &pending)
{
    EmulatorConfig &c = options.config;
    if (option == "--help" || option == "-h")
        options.help = true;
    else if (option == "--k51-2")
        pending.k51Type2 = true;
    else if (option == "--fast")
        options.fast = true;
    else if (option == "--noise")
        c.noise = true;
    else if (option == "--silent")
        c.silentAfterReplies = 0;
    else if (option == "--verbose")
        options.verbose = true;
    else
        return false;
    return true;
}

// Options with a value. Sets `error` (unknown option or bad value) and returns false on failure.
bool parseValue(const std::string &option, const std::string &value, Options &options,
                Pending &pending, std::string &error)
{
    EmulatorConfig &c = options.config;
    long long n = 0;
    if (option == "--family") {
        const auto family = familyFromId(value);
        if (family == Family::Table) {
            error = "--family table: a table goes to a K51 in table mode: use --konfig6 3";
            return false;
        }
        if (!family)
            error = "--family: '" + value + "' is not anc, k51 or hedit";
        else
            c.family = *family;
        return family.has_value();
    }
    if (option == "--image") {
        pending.imagePath = value;
        return true;
    }
    if (option == "--header") {
        c.header = headerFromText(value);
        return true;
    }
    if (option == "--selector") {
        if (value != "pgn" && value != "other")
            error = "--selector: '" + value + "' is not pgn or other";
        c.selectorInPgn = value == "pgn";
        return error.empty();
    }
    if (option == "--store") {
        options.storePath = value;
        return true;
    }
    if (option == "--z-start")
        return parseLength(option, value, c.zStartUm, error);
    if (option == "--z-speed") {
        if (!parseLength(option, value, c.zSpeedUmPerS, error))
            return false;
        if (c.zSpeedUmPerS <= 0)
            error = "--z-speed must be positive";
        return c.zSpeedUmPerS > 0;
    }
    struct NumberOption
    {
        const char *name;
        long long lo, hi;
        std::function<void(long long)> set;
    };
    const NumberOption numbers[] = {
        {"--konfig6", 0, 255, [&](long long v) { pending.konfig6 = int(v); }},
        {"--see-konfig6", 0, 3, [&](long long v) { pending.seeKonfig6 = int(v); }},
        {"--zform", 1, 2, [&](long long v) { c.zForm = int(v); }},
        {"--baud", 50, 4000000, [&](long long v) { options.baud = int(v); }},
        {"--reply-delay-ms", 0, 600000, [&](long long v) { c.replyDelayUs = v * 1000; }},
        {"--naks", 0, 1000000, [&](long long v) { c.nakCount = int(v); }},
        {"--corrupt", 0, 1000000, [&](long long v) { c.corruptCount = int(v); }},
        {"--silent-after", 0, 1000000, [&](long long v) { c.silentAfterReplies = int(v); }},
    };
    for (const NumberOption &number : numbers) {
        if (option != number.name)
            continue;
        if (!parseNumber(option, value, number.lo, number.hi, n, error))
            return false;
        number.set(n);
        return true;
    }
    error = "unknown option '" + option + "' (see --help)";
    return false;
}

// Checks what depends on several options and loads the image file.
bool finish(const Pending &pending, Options &options, std::string &error)
{
    EmulatorConfig &c = options.config;
    auto mode = transferModeFromKonfig6(pending.konfig6, pending.k51Type2);
    if (!mode) {
        // The manual: an unexpected EEPROM value (usually FF) is programmed at power-on with
        // SEE_KONFIG6 from KONFIG.A51.
        const int see = pending.seeKonfig6 >= 0 ? pending.seeKonfig6 : pending.k51Type2 ? 1 : 2;
        mode = transferModeFromKonfig6(see, pending.k51Type2);
        if (mode)
            options.note = "KONFIG6 = " + std::to_string(pending.konfig6) +
                           " is not a transfer mode: at power-on the firmware programs "
                           "SEE_KONFIG6 = " +
                           std::to_string(see);
    }
    if (!mode) {
        error = "--konfig6 " + std::to_string(pending.konfig6) + " is not a transfer mode of " +
                (pending.k51Type2 ? "K51-2 (0 or 1)" : "K51-1 (0 to 3)");
        return false;
    }
    c.mode = *mode;
    if (pending.imagePath.empty())
        return true;
    if (!readFile(pending.imagePath, c.image)) {
        error = "--image: cannot read '" + pending.imagePath + "'";
        return false;
    }
    if (c.image.empty() || c.image.size() + kHeaderSize > kMaxPayload) {
        error = "--image: '" + pending.imagePath + "' has " + std::to_string(c.image.size()) +
                " bytes; a message carries 1 to 65519";
        return false;
    }
    return true;
}

} // namespace

bool parseOptions(const std::vector<std::string> &args, Options &options, std::string &error)
{
    Pending pending;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string &option = args[i];
        if (parseFlag(option, options, pending))
            continue;
        if (option.rfind("--", 0) == 0 && i + 1 >= args.size()) {
            error = option + " needs a value (or is unknown; see --help)";
            return false;
        }
        if (!parseValue(option, i + 1 < args.size() ? args[i + 1] : std::string(), options, pending,
                        error))
            return false;
        ++i;
    }
    return finish(pending, options, error);
}

} // namespace frezka::k51emu
