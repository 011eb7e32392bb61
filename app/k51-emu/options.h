#pragma once
// Command line of k51-emu (see usageText()).

#include "driver/grinder/controlleremulator.h"

#include <string>
#include <vector>

namespace frezka::k51emu {

struct Options
{
    grinder::EmulatorConfig config;
    int baud = 0;          // 0: the family's rate (ANC 4800, K51/HEDIT 9600)
    bool fast = false;     // no baud pacing
    std::string storePath; // write the image here after every load
    bool verbose = false;
    bool help = false;
    std::string note; // said on stderr at start (e.g. the firmware default taken for KONFIG6)
};

std::string usageText();
// Parses argv[1..]; on error returns false with an English message in `error`.
bool parseOptions(const std::vector<std::string> &args, Options &options, std::string &error);

} // namespace frezka::k51emu
