// Values and expressions of RS274/NGC (LinuxCNC): numbers, #parameters, [expressions] with the
// binary operators in LinuxCNC's five precedence levels (left associative, ** included), and
// the unary functions (angles in degrees). Part of Parser.
#include "parser.h"

#include <charconv>
#include <cmath>
#include <numbers>

namespace frezka::gcode {

namespace {

enum Op : int { kPow, kMul, kDiv, kMod, kAdd, kSub, kAnd, kOr, kXor, kEq, kNe, kGt, kGe, kLt, kLe };

constexpr int kPrecedence[] = {6, 5, 5, 5, 4, 4, 2, 2, 2, 3, 3, 3, 3, 3, 3};
constexpr double kToleranceEqual = 0.0001; // LinuxCNC's TOLERANCE_EQUAL for EQ/NE
constexpr double kDegToRad = std::numbers::pi / 180.0;

constexpr double kPow10[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                             1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}

// 0..9 for a digit, above 9 for any other character.
unsigned digitValue(char c)
{
    return static_cast<unsigned>(static_cast<unsigned char>(c)) - unsigned{'0'};
}

// More than 15 significant digits: std::from_chars (rare; kept out of readNumber's fast path,
// whose register saves it would otherwise add to every number).
[[gnu::noinline]] bool readLongNumber(const char *first, const char *last, double *value)
{
    const auto result = std::from_chars(first, last, *value, std::chars_format::fixed);
    return result.ec == std::errc() && result.ptr == last;
}

} // namespace

bool Parser::readNumber(double *value, Error *error)
{
    // A NUL follows m_text's last character (normalize) and stops every loop below (no bounds
    // checks: this runs for every number of a program).
    const char *s = m_text.data();
    const std::size_t start = m_pos;
    std::size_t p = m_pos;
    const bool negative = s[p] == '-';
    p += (s[p] == '+' || s[p] == '-') ? 1 : 0;
    const std::size_t body = p;
    // Up to 15 significant digits the value is mantissa / 10^k, a single correctly rounded
    // division of two exact doubles (Clinger's fast path): the same result as strtod.
    std::uint64_t mantissa = 0;
    unsigned digit = 0;
    while ((digit = digitValue(s[p])) <= 9) {
        mantissa = mantissa * 10 + digit;
        ++p;
    }
    std::size_t digits = p - body;
    std::size_t fraction = 0;
    if (s[p] == '.') {
        const std::size_t first = ++p;
        while ((digit = digitValue(s[p])) <= 9) {
            mantissa = mantissa * 10 + digit;
            ++p;
        }
        fraction = p - first;
        digits += fraction;
    }
    double v = 0;
    if (digits == 0 || (digits > 15 && !readLongNumber(s + body, s + p, &v)))
        return fail(ErrorCode::NumberExpected, start, {}, error);
    if (digits <= 15)
        v = static_cast<double>(mantissa) / kPow10[fraction];
    *value = negative ? -v : v;
    m_pos = p;
    return true;
}

bool Parser::readRealValue(double *value, Error *error)
{
    const char first = m_pos < m_text.size() ? m_text[m_pos] : '\0';
    if (isDigit(first) || first == '.')
        return readNumber(value, error); // the common case, before the checks below
    if (m_pos >= m_text.size())
        return fail(ErrorCode::NumberExpected, m_pos, {}, error);
    const char c = m_text[m_pos];
    const char c1 = m_pos + 1 < m_text.size() ? m_text[m_pos + 1] : '\0';
    if (c == '[')
        return readExpression(value, error);
    if (c == '#')
        return readParameter(value, error);
    if ((c == '+' || c == '-') && c1 != '\0' && !isDigit(c1) && c1 != '.') {
        ++m_pos;
        if (!readRealValue(value, error))
            return false;
        if (c == '-')
            *value = -*value;
        return true;
    }
    if (c >= 'a' && c <= 'z')
        return readUnary(value, error);
    return readNumber(value, error);
}

bool Parser::readInteger(double *value, std::size_t startPos, Error *error)
{
    double v = 0;
    if (!readRealValue(&v, error))
        return false;
    double i = std::floor(v);
    if (v - i > 0.9999)
        i = std::ceil(v);
    else if (v - i > 0.0001) {
        const char c = m_text[startPos];
        return fail(ErrorCode::NonIntegerValue, startPos,
                    std::string(1, (c >= 'a' && c <= 'z') ? static_cast<char>(c - 32) : c), error);
    }
    *value = i;
    return true;
}

bool Parser::readExpression(double *value, Error *error)
{
    const std::size_t open = m_pos;
    ++m_pos; // '['
    if (!readBinary(1, value, error))
        return false;
    if (m_pos >= m_text.size())
        return fail(ErrorCode::UnclosedBracket, open, {}, error);
    if (m_text[m_pos] != ']') {
        std::size_t len = 0;
        int op = 0;
        if (readOperator(&op, &len))
            return fail(ErrorCode::ExpressionExpected, m_pos, {}, error);
        std::size_t end = m_pos;
        while (end < m_text.size() && m_text[end] >= 'a' && m_text[end] <= 'z')
            ++end;
        return fail(ErrorCode::UnknownOperator, m_pos,
                    std::string(m_text, m_pos, std::max<std::size_t>(1, end - m_pos)), error);
    }
    ++m_pos;
    return true;
}

bool Parser::readOperator(int *op, std::size_t *length) const
{
    const std::string_view s = std::string_view(m_text).substr(m_pos);
    struct Spelling
    {
        const char *text;
        Op op;
    };
    static constexpr Spelling kOps[] = {
        {"**", kPow},  {"*", kMul},   {"/", kDiv},   {"+", kAdd}, {"-", kSub},
        {"mod", kMod}, {"and", kAnd}, {"xor", kXor}, {"or", kOr}, {"eq", kEq},
        {"ne", kNe},   {"gt", kGt},   {"ge", kGe},   {"lt", kLt}, {"le", kLe},
    };
    for (const Spelling &sp : kOps) {
        const std::string_view t(sp.text);
        if (s.substr(0, t.size()) == t) {
            *op = sp.op;
            *length = t.size();
            return true;
        }
    }
    return false;
}

bool Parser::readBinary(int minPrecedence, double *value, Error *error)
{
    double left = 0;
    if (!readRealValue(&left, error))
        return false;
    for (;;) {
        int op = 0;
        std::size_t len = 0;
        if (m_pos >= m_text.size() || m_text[m_pos] == ']' || !readOperator(&op, &len))
            break;
        const int prec = kPrecedence[op];
        if (prec < minPrecedence)
            break;
        const std::size_t opPos = m_pos;
        m_pos += len;
        double right = 0;
        if (!readBinary(prec + 1, &right, error))
            return false;
        if (!applyOperator(op, left, right, &left, opPos, error))
            return false;
    }
    *value = left;
    return true;
}

bool Parser::applyOperator(int op, double l, double r, double *out, std::size_t pos,
                           Error *error) const
{
    switch (op) {
    case kPow:
        if (l < 0 && std::floor(r) != r)
            return fail(ErrorCode::NegativePower, pos, {}, error);
        *out = std::pow(l, r);
        return true;
    case kMul:
        *out = l * r;
        return true;
    case kDiv:
        if (r == 0.0)
            return fail(ErrorCode::DivisionByZero, pos, {}, error);
        *out = l / r;
        return true;
    case kMod: {
        if (r == 0.0)
            return fail(ErrorCode::DivisionByZero, pos, {}, error);
        double m = std::fmod(l, r);
        if (m < 0)
            m += std::fabs(r);
        *out = m;
        return true;
    }
    case kAdd:
        *out = l + r;
        return true;
    case kSub:
        *out = l - r;
        return true;
    case kAnd:
        *out = (l == 0.0 || r == 0.0) ? 0.0 : 1.0;
        return true;
    case kOr:
        *out = (l != 0.0 || r != 0.0) ? 1.0 : 0.0;
        return true;
    case kXor:
        *out = ((l == 0.0) != (r == 0.0)) ? 1.0 : 0.0;
        return true;
    case kEq:
        *out = std::fabs(l - r) < kToleranceEqual ? 1.0 : 0.0;
        return true;
    case kNe:
        *out = std::fabs(l - r) >= kToleranceEqual ? 1.0 : 0.0;
        return true;
    case kGt:
        *out = l > r ? 1.0 : 0.0;
        return true;
    case kGe:
        *out = l >= r ? 1.0 : 0.0;
        return true;
    case kLt:
        *out = l < r ? 1.0 : 0.0;
        return true;
    case kLe:
        *out = l <= r ? 1.0 : 0.0;
        return true;
    }
    return fail(ErrorCode::UnknownOperator, pos, {}, error);
}

// One branch per unary function of rs274ngc (abs, acos, ... exists): a table, kept whole.
bool Parser::readUnary(double *value, Error *error)
{
    const std::size_t start = m_pos;
    while (m_pos < m_text.size() && m_text[m_pos] >= 'a' && m_text[m_pos] <= 'z')
        ++m_pos;
    const std::string name(m_text, start, m_pos - start);
    static constexpr const char *kFunctions[] = {"abs", "acos", "asin", "atan",  "cos",
                                                 "exp", "fix",  "fup",  "ln",    "round",
                                                 "sin", "sqrt", "tan",  "exists"};
    bool known = false;
    for (const char *f : kFunctions)
        known = known || name == f;
    if (!known && name.size() == 1) {
        m_pos = start; // a letter where a value belongs: "X Y1"
        return fail(ErrorCode::NumberExpected, start, {}, error);
    }
    if (!known)
        return fail(ErrorCode::UnknownFunction, start, name, error);
    if (m_pos >= m_text.size() || m_text[m_pos] != '[')
        return fail(ErrorCode::ExpressionExpected, m_pos, "after " + name, error);
    if (name == "exists")
        return readExists(start, value, error);
    double a = 0;
    if (!readExpression(&a, error))
        return false;
    const auto domain = [&]() { return fail(ErrorCode::DomainError, start, name, error); };
    if (name == "atan") {
        if (m_pos >= m_text.size() || m_text[m_pos] != '/')
            return fail(ErrorCode::ExpressionExpected, m_pos, "after atan[...]/", error);
        ++m_pos;
        if (m_pos >= m_text.size() || m_text[m_pos] != '[')
            return fail(ErrorCode::ExpressionExpected, m_pos, "after atan[...]/", error);
        double b = 0;
        if (!readExpression(&b, error))
            return false;
        *value = std::atan2(a, b) / kDegToRad;
    } else if (name == "abs") {
        *value = std::fabs(a);
    } else if (name == "acos") {
        if (a < -1.0 || a > 1.0)
            return domain();
        *value = std::acos(a) / kDegToRad;
    } else if (name == "asin") {
        if (a < -1.0 || a > 1.0)
            return domain();
        *value = std::asin(a) / kDegToRad;
    } else if (name == "cos") {
        *value = std::cos(a * kDegToRad);
    } else if (name == "exp") {
        *value = std::exp(a);
    } else if (name == "fix") {
        *value = std::floor(a);
    } else if (name == "fup") {
        *value = std::ceil(a);
    } else if (name == "ln") {
        if (a <= 0.0)
            return domain();
        *value = std::log(a);
    } else if (name == "round") {
        // LinuxCNC: (int)(a +- 0.5); beyond 2^53 every double is already whole.
        *value = std::fabs(a) < 4.5e15
                     ? static_cast<double>(static_cast<long long>(a + (a < 0 ? -0.5 : 0.5)))
                     : a;
    } else if (name == "sin") {
        *value = std::sin(a * kDegToRad);
    } else if (name == "sqrt") {
        if (a < 0.0)
            return domain();
        *value = std::sqrt(a);
    } else { // tan
        *value = std::tan(a * kDegToRad);
    }
    return true;
}

// exists[#<name>] (1 when the parameter has a value) or exists[#n] (LinuxCNC: 1 when n, any
// integer value such as ##1 or #[1+1], names a parameter of #1..#5601; 0 otherwise, no error).
bool Parser::readExists(std::size_t start, double *value, Error *error)
{
    ++m_pos; // '['
    if (m_pos >= m_text.size() || m_text[m_pos] != '#')
        return fail(ErrorCode::BadParameterName, m_pos, "exists", error);
    ++m_pos;
    if (m_pos < m_text.size() && m_text[m_pos] == '<') {
        std::string_view pname;
        if (!readName(&pname, error))
            return false;
        double dummy = 0;
        *value = m_params.named(pname, &dummy) ? 1.0 : 0.0;
    } else {
        double index = 0;
        if (!readInteger(&index, m_pos - 1, error))
            return false;
        *value = index >= 1 && index < Parameters::kCount ? 1.0 : 0.0;
    }
    if (m_pos >= m_text.size() || m_text[m_pos] != ']')
        return fail(ErrorCode::UnclosedBracket, start, {}, error);
    ++m_pos;
    return true;
}

bool Parser::readName(std::string_view *name, Error *error)
{
    // At '<'.
    const std::size_t start = m_pos;
    const std::size_t end = m_text.find('>', m_pos);
    if (end == std::string::npos || end == m_pos + 1)
        return fail(ErrorCode::BadParameterName, start, std::string(m_text.substr(start)), error);
    *name = std::string_view(m_text).substr(m_pos + 1, end - m_pos - 1);
    m_pos = end + 1;
    return true;
}

bool Parser::readParameterRef(int *index, std::string_view *name, Error *error)
{
    const std::size_t start = m_pos;
    ++m_pos; // '#'
    *index = 0;
    *name = {};
    if (m_pos < m_text.size() && m_text[m_pos] == '<')
        return readName(name, error);
    double v = 0;
    if (!readInteger(&v, start, error)) {
        if (error->code == ErrorCode::NumberExpected)
            error->detail = "#";
        return false;
    }
    if (v < 1 || v >= Parameters::kCount)
        return fail(ErrorCode::ParameterOutOfRange, start, std::to_string(v), error);
    *index = static_cast<int>(v);
    return true;
}

bool Parser::readParameter(double *value, Error *error)
{
    const std::size_t start = m_pos;
    int index = 0;
    std::string_view name;
    if (!readParameterRef(&index, &name, error))
        return false;
    if (index != 0) {
        *value = m_params.numbered(index);
        return true;
    }
    if (!m_params.named(name, value))
        return fail(ErrorCode::NamedParameterUndefined, start, "#<" + std::string(name) + ">",
                    error);
    return true;
}

} // namespace frezka::gcode
