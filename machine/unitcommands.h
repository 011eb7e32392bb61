#pragma once
// UnitCommands: the commands of a unit program, stored compactly (issue 17).
//
// A UnitCommand is 72 bytes as a value; a 5-million-vector program held them as a vector of
// 360 MB. Here each command is one 24-byte record (its op, its source line and 16 bytes of
// arguments: the relative steps d of a motion command, or the value and aux of the others), and
// the end positions are not stored but summed: endSteps of a motion command is the end before it
// plus its d, of any other the end before it, and a mark every kMarkEvery commands holds the end
// before it (2 bytes a command), so the end of any command is at most kMarkEvery - 1 additions
// away. A command that does not fit that form (a motion with a value or aux, such as a probe
// with its kind; anything else with steps; an end that is not the sum) is kept whole beside the
// records, so every UnitCommand reads back exactly as it was stored.
//
// The container reads like a std::vector<UnitCommand> whose elements are values: operator[],
// front(), back() and the iterators return a UnitCommand (not a reference), so code that reads
// `const UnitCommand &c = commands[i]` or loops `for (const auto &c : commands)` is unchanged;
// a change goes through push_back, set, insert, erase, pop_back or erase_if.

#include "machine/unitcommand.h"

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <vector>

namespace frezka::machine {

class UnitCommands
{
public:
    static constexpr std::size_t kMarkEvery = 16;

    // A proxy iterator as std::vector<bool>'s: random access, its reference is a value. Walked
    // one by one it carries the end before its command, so that a walk over the whole program
    // costs one record a command (a jump sums from the mark before it once).
    class const_iterator
    {
    public:
        using iterator_category = std::random_access_iterator_tag;
        using value_type = UnitCommand;
        using difference_type = std::ptrdiff_t;
        using reference = UnitCommand;
        using pointer = void;

        const_iterator() = default;
        const_iterator(const UnitCommands *owner, std::size_t index)
            : m_owner(owner)
            , m_index(index)
        {}
        UnitCommand operator*() const;
        UnitCommand operator[](difference_type n) const
        {
            return (*m_owner)[std::size_t(difference_type(m_index) + n)];
        }
        const_iterator &operator++();
        const_iterator operator++(int)
        {
            const_iterator before = *this;
            ++*this;
            return before;
        }
        const_iterator &operator--() { return *this -= 1; }
        const_iterator operator--(int)
        {
            const_iterator before = *this;
            --*this;
            return before;
        }
        const_iterator &operator+=(difference_type n)
        {
            m_index = std::size_t(difference_type(m_index) + n);
            m_known = false;
            return *this;
        }
        const_iterator &operator-=(difference_type n) { return *this += -n; }
        friend const_iterator operator+(const_iterator it, difference_type n) { return it += n; }
        friend const_iterator operator+(difference_type n, const_iterator it) { return it += n; }
        friend const_iterator operator-(const_iterator it, difference_type n) { return it -= n; }
        friend difference_type operator-(const const_iterator &a, const const_iterator &b)
        {
            return difference_type(a.m_index) - difference_type(b.m_index);
        }
        friend bool operator==(const const_iterator &a, const const_iterator &b)
        {
            return a.m_index == b.m_index;
        }
        friend auto operator<=>(const const_iterator &a, const const_iterator &b)
        {
            return a.m_index <=> b.m_index;
        }
        std::size_t index() const { return m_index; }

    private:
        friend class UnitCommands;
        const UnitCommands *m_owner = nullptr;
        std::size_t m_index = 0;
        bool m_known = false; // m_before is the end before command m_index
        Steps4 m_before{};
    };
    using iterator = const_iterator;
    using value_type = UnitCommand;
    using size_type = std::size_t;
    using difference_type = std::ptrdiff_t;
    using reference = UnitCommand;
    using const_reference = UnitCommand;

    UnitCommands() = default;
    UnitCommands(std::initializer_list<UnitCommand> commands);
    UnitCommands(const std::vector<UnitCommand> &commands); // NOLINT: reads as the vector it was

    std::size_t size() const { return m_records.size(); }
    bool empty() const { return m_records.empty(); }
    UnitCommand operator[](std::size_t i) const;
    UnitCommand at(std::size_t i) const { return (*this)[i]; }
    UnitCommand front() const { return (*this)[0]; }
    UnitCommand back() const { return (*this)[size() - 1]; }
    // Command i's op alone (no end position summed).
    UnitOp op(std::size_t i) const
    {
        const Record &r = m_records[i];
        return r.whole ? m_whole[std::size_t(r.arg[0])].op : r.op;
    }
    // The end position of command i alone (cheaper than the whole command).
    Steps4 endSteps(std::size_t i) const;
    const_iterator begin() const;
    const_iterator end() const { return {this, size()}; }
    const_iterator cbegin() const { return begin(); }
    const_iterator cend() const { return end(); }

    void push_back(const UnitCommand &c);
    void reserve(std::size_t n);
    std::size_t capacity() const { return m_records.capacity(); }
    void shrink_to_fit();
    void clear();
    // Replaces command i; the commands after it keep their own end positions.
    void set(std::size_t i, const UnitCommand &c);
    void pop_back();
    const_iterator insert(const_iterator at, const UnitCommand &c);
    const_iterator erase(const_iterator at);
    std::vector<UnitCommand> toVector() const;
    // Bytes held (records, marks and whole commands), for the benches.
    std::size_t bytes() const;

    friend bool operator==(const UnitCommands &a, const UnitCommands &b);

    template<typename Pred>
    friend std::size_t erase_if(UnitCommands &commands, Pred pred)
    {
        UnitCommands kept;
        kept.reserve(commands.size());
        for (std::size_t i = 0; i < commands.size(); ++i) {
            const UnitCommand c = commands[i];
            if (!pred(c))
                kept.push_back(c);
        }
        const std::size_t removed = commands.size() - kept.size();
        kept.shrink_to_fit();
        commands = std::move(kept);
        return removed;
    }

private:
    struct Record
    {
        std::int32_t arg[4]{};  // d (motion), or value low, value high, aux; or the whole's index
        std::uint32_t line = 0; // sourceLine
        UnitOp op = UnitOp::Line;
        std::uint8_t whole = 0; // 1: the command is m_whole[arg[0]]
        std::uint16_t unused = 0;
    };
    static_assert(sizeof(Record) == 24);

    void assign(const std::vector<UnitCommand> &commands);
    // The end after record i, given the end before it.
    void advance(std::size_t i, Steps4 &end) const;
    UnitCommand decoded(std::size_t i, const Steps4 &before) const;

    std::vector<Record> m_records;
    std::vector<Steps4> m_marks;      // the end before commands 0, kMarkEvery, 2 kMarkEvery, ...
    std::vector<UnitCommand> m_whole; // the commands that do not fit a record
    Steps4 m_end{};                   // the end after the last command
};

} // namespace frezka::machine
