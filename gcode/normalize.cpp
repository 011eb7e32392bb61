// Parser::normalize: a source line without comments, spaces, tabs and CRs, in lower case. It runs
// for every line of a program, so it reads 16 bytes at a time where it can (SSE2, which every
// x86-64 has): a block without ';', '(' or NUL is lower-cased in one step and its kept bytes are
// copied out in runs between the dropped ones. The rest of a line (a block with a comment, the
// bytes near the end of the text) goes through the one-character-at-a-time loop, whose result is
// the same.
#include "parser.h"

#include <algorithm>
#include <array>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace frezka::gcode {

namespace {

constexpr std::size_t kBlock = 16;

// normalize()'s reading of a character: 0 dropped (space, tab, CR), 1 looked at (';', '(' and
// NUL, which is kept), any other value the character kept, upper case made lower.
constexpr std::array<unsigned char, 256> kNormalized = [] {
    std::array<unsigned char, 256> table{};
    for (int c = 0; c < 256; ++c)
        table[c] = static_cast<unsigned char>(c >= 'A' && c <= 'Z' ? c + 32 : c);
    table[' '] = table['\t'] = table['\r'] = 0;
    table[';'] = table['('] = table[0] = 1;
    return table;
}();

#if defined(__SSE2__)
// Normalizes whole blocks of s[0, n) into *out (which has kBlock bytes of room past what it
// keeps) while 16 bytes can be read (n + readableAfter) and a block has no ';', '(' or NUL among
// its first n bytes. Returns where the character loop goes on.
std::size_t normalizeBlocks(const char *s, std::size_t n, std::size_t readableAfter, char **out)
{
    const __m128i space = _mm_set1_epi8(' '), tab = _mm_set1_epi8('\t'), cr = _mm_set1_epi8('\r'),
                  semicolon = _mm_set1_epi8(';'), paren = _mm_set1_epi8('('),
                  zero = _mm_setzero_si128(), beforeA = _mm_set1_epi8('A' - 1),
                  afterZ = _mm_set1_epi8('Z' + 1), caseBit = _mm_set1_epi8(0x20);
    char *o = *out;
    std::size_t i = 0;
    while (i < n && i + kBlock <= n + readableAfter) {
        const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i *>(s + i));
        const std::size_t valid = std::min(kBlock, n - i);
        const unsigned inLine = valid == kBlock ? 0xFFFFu : (1u << valid) - 1;
        const __m128i special =
            _mm_or_si128(_mm_or_si128(_mm_cmpeq_epi8(v, semicolon), _mm_cmpeq_epi8(v, paren)),
                         _mm_cmpeq_epi8(v, zero));
        if (static_cast<unsigned>(_mm_movemask_epi8(special)) & inLine)
            break;
        const __m128i dropped = _mm_or_si128(
            _mm_or_si128(_mm_cmpeq_epi8(v, space), _mm_cmpeq_epi8(v, tab)), _mm_cmpeq_epi8(v, cr));
        unsigned keep = ~static_cast<unsigned>(_mm_movemask_epi8(dropped)) & inLine;
        const __m128i upper = _mm_and_si128(_mm_cmpgt_epi8(v, beforeA), _mm_cmplt_epi8(v, afterZ));
        const __m128i lower = _mm_or_si128(v, _mm_and_si128(upper, caseBit));
        alignas(16) char bytes[2 * kBlock];
        _mm_store_si128(reinterpret_cast<__m128i *>(bytes), lower);
        while (keep) {
            // A run of kept bytes: one 16-byte copy (what lies past the run is overwritten next).
            const int first = __builtin_ctz(keep);
            const int length = __builtin_ctz(~(keep >> first));
            std::memcpy(o, bytes + first, kBlock);
            o += length;
            keep &= ~(((1u << length) - 1) << first);
        }
        i += valid;
    }
    *out = o;
    return i;
}
#endif

} // namespace

std::size_t countNewlines(std::string_view text)
{
    const char *s = text.data();
    const std::size_t n = text.size();
    std::size_t count = 0, i = 0;
#if defined(__SSE2__)
    // Each byte lane counts its matches (up to 255 blocks), then the lanes are summed.
    const __m128i newline = _mm_set1_epi8('\n'), zero = _mm_setzero_si128();
    while (i + kBlock <= n) {
        const std::size_t end = i + std::min(n - i, 255 * kBlock);
        __m128i lanes = zero;
        for (; i + kBlock <= end; i += kBlock) {
            const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i *>(s + i));
            lanes = _mm_sub_epi8(lanes, _mm_cmpeq_epi8(v, newline));
        }
        const __m128i sums = _mm_sad_epu8(lanes, zero);
        count += static_cast<std::size_t>(_mm_cvtsi128_si32(sums)) +
                 static_cast<std::size_t>(_mm_extract_epi16(sums, 4));
    }
#endif
    for (; i < n; ++i)
        count += s[i] == '\n' ? 1 : 0;
    return count;
}

bool Parser::normalize(std::string_view raw, std::uint32_t line, Error *error,
                       std::size_t readableAfter)
{
    m_line = line;
    m_raw = raw;
    m_blockDelete = false;
    m_abortColumn = 0;
    m_abortText.clear();
    if (raw.size() > 65535) {
        m_text = {};
        *error = {ErrorCode::LineTooLong, line, 1, std::to_string(raw.size()), {}};
        return false;
    }
    const char *s = raw.data();
    const std::size_t n = raw.size();
    if (m_buffer.size() < n + kBlock + 1)
        m_buffer.resize(n + kBlock + 1); // room for the block copies and the NUL
    char *out = m_buffer.data();
    char *const begin = out;
    std::size_t i = 0;
#if defined(__SSE2__)
    i = normalizeBlocks(s, n, readableAfter, &out);
#else
    (void)readableAfter;
#endif
    for (; i < n; ++i) {
        // One table look-up a character; the byte is stored whatever it is and kept by moving on.
        const unsigned char kept = kNormalized[static_cast<unsigned char>(s[i])];
        *out = static_cast<char>(kept);
        out += kept > 1;
        if (kept != 1)
            continue;
        const char c = s[i];
        if (c == '\0') {
            *out++ = c;
            continue;
        }
        if (c == ';')
            break;
        const std::size_t open = i; // '('
        for (++i; i < n && s[i] != ')'; ++i) {
            if (s[i] == '(') {
                m_text = {};
                *error = {
                    ErrorCode::NestedComment, line, static_cast<std::uint32_t>(i + 1), {}, {}};
                return false;
            }
        }
        if (i >= n) {
            m_text = {};
            *error = {
                ErrorCode::UnclosedComment, line, static_cast<std::uint32_t>(open + 1), {}, {}};
            return false;
        }
        noteAbortComment(raw.substr(open + 1, i - open - 1), open);
    }
    *out = '\0';
    m_text = std::string_view(begin, static_cast<std::size_t>(out - begin));
    if (!m_text.empty() && m_text[0] == '/') {
        m_blockDelete = true;
        m_text.remove_prefix(1);
    }
    return true;
}

// LinuxCNC's (abort, text): the comment's first word, any case, spaces before it allowed.
void Parser::noteAbortComment(std::string_view comment, std::size_t open)
{
    const std::size_t at = comment.find_first_not_of(" \t");
    if (at == std::string_view::npos || comment.size() - at < 6)
        return;
    std::string word(comment.substr(at, 6));
    for (char &c : word)
        c = (c >= 'A' && c <= 'Z') ? static_cast<char>(c + 32) : c;
    if (word != "abort," || m_abortColumn != 0)
        return;
    m_abortColumn = static_cast<std::uint32_t>(open + 1);
    std::string_view text = comment.substr(at + 6);
    while (!text.empty() && text.front() == ' ')
        text.remove_prefix(1);
    m_abortText = std::string(text);
}

} // namespace frezka::gcode
