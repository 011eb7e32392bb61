#pragma once
// RS274/NGC parameters: numbered #1..#5601, local named #<name> (one scope per subroutine call)
// and global named #<_name>. System parameters (#5161.., #5220, #5420.., #<_x>, ...) are not
// stored here: they are computed from the interpreter's state through SystemParameters.

#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace frezka::gcode {

class SystemParameters
{
public:
    virtual ~SystemParameters() = default;
    // Numbered system parameter (#5000 and up); false if the index is not a system parameter.
    virtual bool systemNumbered(int index, double *value) const = 0;
    // Predefined named parameter such as "_x" (lower case, without #< >); false if unknown.
    virtual bool systemNamed(std::string_view name, double *value) const = 0;
};

class Parameters
{
public:
    static constexpr int kCount = 5602;       // #0..#5601, as LinuxCNC
    static constexpr int kFirstSystem = 5000; // from here on the interpreter owns the values
    static constexpr int kArgCount = 30;      // #1..#30 are subroutine arguments

    Parameters();
    void setSystem(const SystemParameters *system) { m_system = system; }

    // Value of #index; numbers out of range are rejected by the caller.
    double numbered(int index) const;
    void setNumbered(int index, double value) { m_numbered[index] = value; }
    // LinuxCNC lets programs write #5599 (its switch for (DEBUG,...) and (PRINT,...) output,
    // which Frezka treats as comments); the other system values stay read-only here (LinuxCNC
    // lets programs write most of them, e.g. #5070, the probe result).
    bool isReadOnly(int index) const
    {
        return (index >= kFirstSystem && index != 5599) || index == 0;
    }

    // Named parameters; the name is lower case without the brackets. Names starting with '_'
    // are global, the others local to the current subroutine call.
    bool named(std::string_view name, double *value) const;
    void setNamed(std::string_view name, double value);
    bool isSystemName(std::string_view name) const;

    // Subroutine calls: a new local scope and saved #1..#30.
    void pushScope();
    void popScope();
    std::size_t depth() const { return m_locals.size(); }

private:
    struct Hash
    {
        using is_transparent = void;
        std::size_t operator()(std::string_view s) const
        {
            return std::hash<std::string_view>{}(s);
        }
    };
    using Map = std::unordered_map<std::string, double, Hash, std::equal_to<>>;

    const SystemParameters *m_system = nullptr;
    std::vector<double> m_numbered;
    std::vector<Map> m_locals; // back() is the current scope
    std::vector<std::array<double, kArgCount>> m_savedArgs;
    Map m_globals;
};

} // namespace frezka::gcode
