#include "parameters.h"

#include <algorithm>

namespace frezka::gcode {

Parameters::Parameters()
    : m_numbered(kCount, 0.0)
    , m_locals(1)
{}

double Parameters::numbered(int index) const
{
    double v = 0;
    if (index >= kFirstSystem && m_system && m_system->systemNumbered(index, &v))
        return v;
    return m_numbered[index];
}

bool Parameters::named(std::string_view name, double *value) const
{
    if (!name.empty() && name.front() == '_') {
        if (m_system && m_system->systemNamed(name, value))
            return true;
        const auto it = m_globals.find(name);
        if (it == m_globals.end())
            return false;
        *value = it->second;
        return true;
    }
    const Map &scope = m_locals.back();
    const auto it = scope.find(name);
    if (it == scope.end())
        return false;
    *value = it->second;
    return true;
}

bool Parameters::isSystemName(std::string_view name) const
{
    double v = 0;
    return !name.empty() && name.front() == '_' && m_system && m_system->systemNamed(name, &v);
}

void Parameters::setNamed(std::string_view name, double value)
{
    Map &map = (!name.empty() && name.front() == '_') ? m_globals : m_locals.back();
    const auto it = map.find(name);
    if (it != map.end())
        it->second = value;
    else
        map.emplace(std::string(name), value);
}

void Parameters::pushScope()
{
    m_locals.emplace_back();
    std::array<double, kArgCount> saved{};
    std::copy_n(m_numbered.begin() + 1, kArgCount, saved.begin());
    m_savedArgs.push_back(saved);
}

void Parameters::popScope()
{
    if (m_locals.size() <= 1)
        return;
    m_locals.pop_back();
    std::copy_n(m_savedArgs.back().begin(), kArgCount, m_numbered.begin() + 1);
    m_savedArgs.pop_back();
}

} // namespace frezka::gcode
