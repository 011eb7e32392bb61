// The interpreter's fast paths (issue 15's speed work) against plain references: the line
// normalized 16 bytes at a time, the JSON numbers rounded without round(), and the JSON writer's
// copies of repeated values.
#include "gcode/parser.h"
#include "gcode/toolpath.h"
#include "gcode/trace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>

using namespace frezka::gcode;

namespace {

// normalize()'s rules one character at a time: blanks dropped, ';' ends the line, (comments)
// dropped (a nested or unclosed one is an error), upper case made lower.
bool referenceNormalize(std::string_view raw, std::string *out, ErrorCode *code)
{
    out->clear();
    for (std::size_t i = 0; i < raw.size(); ++i) {
        const char c = raw[i];
        if (c == ' ' || c == '\t' || c == '\r')
            continue;
        if (c == ';')
            break;
        if (c == '(') {
            for (++i; i < raw.size() && raw[i] != ')'; ++i) {
                if (raw[i] == '(') {
                    *code = ErrorCode::NestedComment;
                    return false;
                }
            }
            if (i >= raw.size()) {
                *code = ErrorCode::UnclosedComment;
                return false;
            }
            continue;
        }
        *out += (c >= 'A' && c <= 'Z') ? static_cast<char>(c + 32) : c;
    }
    if (!out->empty() && (*out)[0] == '/')
        out->erase(0, 1);
    return true;
}

// The JSON number as it was written before: std::round, then the digits.
std::string referenceFixed4(double value)
{
    const double scaled = std::round(value * 10000.0);
    if (std::isnan(value) || std::isinf(value))
        return "null";
    if (!(std::fabs(scaled) < 9.0e15)) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.4e", value);
        return buf;
    }
    const auto n = static_cast<long long>(scaled);
    const unsigned long long u = n < 0 ? static_cast<unsigned long long>(-n) : n;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%llu.%04llu", n < 0 ? "-" : "", u / 10000, u % 10000);
    return buf;
}

} // namespace

TEST(FastPaths, NormalizeInBlocksEqualsTheCharacterRules)
{
    std::mt19937 rng(15);
    const std::string alphabet = "GXYZgxyz0123456789.-+ \t\r;(()) NOMnm#[]<>/%@^Ff\xc3\xa9";
    Parameters params;
    Parser parser(params);
    for (int round = 0; round < 2000; ++round) {
        std::string text;
        for (int line = 0; line < 20; ++line) {
            const std::size_t length = rng() % 60;
            for (std::size_t k = 0; k < length; ++k)
                text += rng() % 300 == 0 ? '\0' : alphabet[rng() % alphabet.size()];
            text += '\n';
        }
        for (std::size_t pos = 0; pos < text.size();) {
            const std::size_t nl = text.find('\n', pos);
            const std::string_view raw(text.data() + pos, nl - pos);
            std::string expected;
            ErrorCode expectedCode{};
            const bool expectedOk = referenceNormalize(raw, &expected, &expectedCode);
            Error error;
            // The rest of the text may be read (as the interpreter allows), not used.
            const bool ok = parser.normalize(raw, 1, &error, text.size() - nl);
            ASSERT_EQ(ok, expectedOk) << raw;
            if (ok)
                ASSERT_EQ(std::string(parser.text()), expected) << raw;
            else
                ASSERT_EQ(error.code, expectedCode) << raw;
            pos = nl + 1;
        }
    }
}

TEST(FastPaths, JsonNumbersRoundHalfAwayFromZeroAsRoundDoes)
{
    std::mt19937_64 rng(15);
    std::uniform_int_distribution<long long> tenThousandths(-100'000'000'000LL, 100'000'000'000LL);
    std::vector<double> values = {0.0,
                                  -0.0,
                                  0.00005,
                                  -0.00005,
                                  0.000049999,
                                  2.5e-5,
                                  123.45675,
                                  -123.45675,
                                  8.99999e11,
                                  9.0e11,
                                  1e300,
                                  std::numeric_limits<double>::quiet_NaN(),
                                  std::numeric_limits<double>::infinity()};
    for (int i = 0; i < 200'000; ++i) {
        const long long k = tenThousandths(rng);
        values.push_back((static_cast<double>(k) + 0.5) / 10000.0); // halves
        values.push_back(static_cast<double>(k) / 1000.0 + 0.00005);
        std::uint64_t bits = rng();
        double any = 0;
        std::memcpy(&any, &bits, sizeof any);
        values.push_back(any);
    }
    for (double v : values) {
        std::string text;
        appendFixed4(text, v);
        ASSERT_EQ(text, referenceFixed4(v)) << std::hexfloat << v;
    }
}

TEST(FastPaths, WrittenJsonLinesEqualTheTraceWithRepeatedValues)
{
    Toolpath tp;
    const double values[] = {0.0, -0.0, 1.5, 1.5, -2.25, std::numeric_limits<double>::quiet_NaN()};
    std::uint32_t line = 1;
    for (double a : values) {
        for (double b : values) {
            tp.appendFeed({a, b, a, 0.0}, b, line++);
            tp.appendRapid({a, a, b, b}, 1200, line++);
        }
        tp.appendEvent({EventKind::Dwell, a, 0, 0}, 1200, line++);
    }
    for (bool events : {false, true}) {
        std::FILE *file = std::tmpfile();
        ASSERT_NE(file, nullptr);
        ASSERT_TRUE(writeJsonLines(tp, file, events));
        std::rewind(file);
        std::string written;
        char buf[4096];
        for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, file)) > 0;)
            written.append(buf, n);
        std::fclose(file);
        EXPECT_EQ(written, jsonLines(tp, events));
    }
}
