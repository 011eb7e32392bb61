// The compact store of a unit program's commands. See unitcommands.h.

#include "machine/unitcommands.h"

#include <cstring>

namespace frezka::machine {

namespace {

bool movesSteps(UnitOp op)
{
    return op == UnitOp::Line || op == UnitOp::Vector || op == UnitOp::Probe;
}

// The end after c, given the end before it, as the planner computes it.
Steps4 predictedEnd(const UnitCommand &c, Steps4 end)
{
    if (movesSteps(c.op)) {
        for (std::size_t a = 0; a < 4; ++a)
            end[a] += c.d[a];
    }
    return end;
}

} // namespace

UnitCommands::UnitCommands(std::initializer_list<UnitCommand> commands)
{
    reserve(commands.size());
    for (const UnitCommand &c : commands)
        push_back(c);
}

UnitCommands::UnitCommands(const std::vector<UnitCommand> &commands)
{
    assign(commands);
}

void UnitCommands::assign(const std::vector<UnitCommand> &commands)
{
    clear();
    reserve(commands.size());
    for (const UnitCommand &c : commands)
        push_back(c);
}

void UnitCommands::push_back(const UnitCommand &c)
{
    if (m_records.empty()) // the end before the first command, so that its own end is the sum
        m_end = movesSteps(c.op) ? Steps4{c.endSteps[0] - c.d[0], c.endSteps[1] - c.d[1],
                                          c.endSteps[2] - c.d[2], c.endSteps[3] - c.d[3]}
                                 : c.endSteps;
    if (m_records.size() % kMarkEvery == 0)
        m_marks.push_back(m_end);
    Record r;
    r.line = c.sourceLine;
    r.op = c.op;
    const bool fits =
        movesSteps(c.op) ? c.value == 0 && c.aux == 0 : c.d == std::array<std::int32_t, 4>{};
    if (fits && predictedEnd(c, m_end) == c.endSteps) {
        if (movesSteps(c.op)) {
            std::memcpy(r.arg, c.d.data(), sizeof r.arg);
        } else {
            const auto value = static_cast<std::uint64_t>(c.value);
            r.arg[0] = static_cast<std::int32_t>(static_cast<std::uint32_t>(value));
            r.arg[1] = static_cast<std::int32_t>(static_cast<std::uint32_t>(value >> 32));
            r.arg[2] = c.aux;
        }
    } else {
        r.whole = 1;
        r.arg[0] = static_cast<std::int32_t>(m_whole.size());
        m_whole.push_back(c);
    }
    m_records.push_back(r);
    m_end = c.endSteps;
}

void UnitCommands::advance(std::size_t i, Steps4 &end) const
{
    const Record &r = m_records[i];
    if (r.whole) {
        end = m_whole[std::size_t(r.arg[0])].endSteps;
    } else if (movesSteps(r.op)) {
        for (std::size_t a = 0; a < 4; ++a)
            end[a] += r.arg[a];
    }
}

Steps4 UnitCommands::endSteps(std::size_t i) const
{
    const std::size_t mark = i / kMarkEvery;
    Steps4 end = m_marks[mark];
    for (std::size_t j = mark * kMarkEvery; j <= i; ++j)
        advance(j, end);
    return end;
}

UnitCommand UnitCommands::operator[](std::size_t i) const
{
    const std::size_t mark = i / kMarkEvery;
    Steps4 before = m_marks[mark];
    for (std::size_t j = mark * kMarkEvery; j < i; ++j)
        advance(j, before);
    return decoded(i, before);
}

// Command i, given the end before it.
UnitCommand UnitCommands::decoded(std::size_t i, const Steps4 &before) const
{
    const Record &r = m_records[i];
    if (r.whole)
        return m_whole[std::size_t(r.arg[0])];
    UnitCommand c;
    c.op = r.op;
    c.sourceLine = r.line;
    c.endSteps = before;
    if (movesSteps(r.op)) {
        std::memcpy(c.d.data(), r.arg, sizeof r.arg);
        for (std::size_t a = 0; a < 4; ++a)
            c.endSteps[a] += c.d[a];
    } else {
        const std::uint64_t low = static_cast<std::uint32_t>(r.arg[0]);
        const std::uint64_t high = static_cast<std::uint32_t>(r.arg[1]);
        c.value = static_cast<std::int64_t>(low | high << 32);
        c.aux = r.arg[2];
    }
    return c;
}

UnitCommands::const_iterator UnitCommands::begin() const
{
    const_iterator it(this, 0);
    if (!m_marks.empty()) {
        it.m_known = true;
        it.m_before = m_marks[0];
    }
    return it;
}

UnitCommand UnitCommands::const_iterator::operator*() const
{
    return m_known ? m_owner->decoded(m_index, m_before) : (*m_owner)[m_index];
}

UnitCommands::const_iterator &UnitCommands::const_iterator::operator++()
{
    if (m_known && m_index < m_owner->size())
        m_owner->advance(m_index, m_before);
    ++m_index;
    return *this;
}

void UnitCommands::reserve(std::size_t n)
{
    m_records.reserve(n);
    m_marks.reserve(n / kMarkEvery + 1);
}

void UnitCommands::shrink_to_fit()
{
    m_records.shrink_to_fit();
    m_marks.shrink_to_fit();
    m_whole.shrink_to_fit();
}

void UnitCommands::clear()
{
    m_records.clear();
    m_marks.clear();
    m_whole.clear();
    m_end = {};
}

std::vector<UnitCommand> UnitCommands::toVector() const
{
    std::vector<UnitCommand> out;
    out.reserve(size());
    for (std::size_t i = 0; i < size(); ++i)
        out.push_back((*this)[i]);
    return out;
}

// The changes in the middle rebuild the store: they are rare (tests, a firmware's dropped VN at
// the start) and a rebuild keeps one way of encoding.
void UnitCommands::set(std::size_t i, const UnitCommand &c)
{
    std::vector<UnitCommand> all = toVector();
    all[i] = c;
    assign(all);
}

void UnitCommands::pop_back()
{
    const Record last = m_records.back();
    m_records.pop_back();
    if (last.whole && std::size_t(last.arg[0]) + 1 == m_whole.size())
        m_whole.pop_back();
    if (m_records.size() % kMarkEvery == 0) { // the mark was the end before the one removed
        m_end = m_marks.back();
        m_marks.pop_back();
    } else {
        m_end = endSteps(m_records.size() - 1);
    }
}

UnitCommands::const_iterator UnitCommands::insert(const_iterator at, const UnitCommand &c)
{
    std::vector<UnitCommand> all = toVector();
    all.insert(all.begin() + at.index(), c);
    assign(all);
    return {this, at.index()};
}

UnitCommands::const_iterator UnitCommands::erase(const_iterator at)
{
    std::vector<UnitCommand> all = toVector();
    all.erase(all.begin() + at.index());
    assign(all);
    return {this, at.index()};
}

std::size_t UnitCommands::bytes() const
{
    return m_records.capacity() * sizeof(Record) + m_marks.capacity() * sizeof(Steps4) +
           m_whole.capacity() * sizeof(UnitCommand);
}

bool operator==(const UnitCommands &a, const UnitCommands &b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!(a[i] == b[i]))
            return false;
    }
    return true;
}

} // namespace frezka::machine
