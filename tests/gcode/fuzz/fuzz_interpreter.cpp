// libFuzzer target: arbitrary bytes through the lexer, parser and interpreter (first-error and
// check mode) and the JSON Lines writer. Built with clang, AddressSanitizer and UBSan by
// run_fuzz.cmake (ctest: gcode.fuzz_interpreter), which runs a bounded number of inputs.
#include "gcode/interpreter.h"
#include "gcode/trace.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    using namespace frezka::gcode;
    const std::string_view text(reinterpret_cast<const char *>(data), size);
    Options options;
    options.maxBlocks = 20000; // endless loops end as TooManyBlocks
    options.maxErrors = 50;
    for (const bool check : {false, true}) {
        options.collectAllErrors = check;
        const Result r = interpretText(text, options);
        for (const Error &e : r.errors) {
            if (englishMessage(e).empty() || e.line == 0)
                __builtin_trap();
        }
        (void)jsonLines(r.toolpath, true);
        (void)summarize(r.toolpath, 1000.0);
    }
    return 0;
}
