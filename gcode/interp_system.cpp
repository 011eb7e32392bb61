// System parameters computed from the interpreter's state: numbered (#5061.., #5161..,
// #5211.., #5220.., #5400.., #5420..) and named (#<_x>, #<_feed>, ...), in program units.
#include "interpreter.h"

namespace frezka::gcode {

bool Interpreter::systemNumbered(int index, double *value) const
{
    const double u = unit();
    auto length = [&](double mm, int axis) { return axis < 3 ? mm / u : mm; };
    auto axisOf = [](int i) { return i; }; // 0..3 = x y z a; b c u v w read as 0
    const Point4 prog = programPosition();
    const double progv[4] = {prog.x, prog.y, prog.z, prog.a};
    const double probe[4] = {m_probe.x, m_probe.y, m_probe.z, m_probe.a};
    if (index >= 5061 && index <= 5069) {
        const int i = index - 5061;
        *value = i < 4 ? length(probe[i], i) : 0;
        return true;
    }
    if (index == 5070) {
        *value = m_probed ? 1 : 0;
        return true;
    }
    if ((index >= 5161 && index <= 5169) || (index >= 5181 && index <= 5189)) {
        const int i = axisOf(index >= 5181 ? index - 5181 : index - 5161);
        const auto &home = index >= 5181 ? m_g30 : m_g28;
        *value = i < 4 ? length(home[i], i) : 0;
        return true;
    }
    if (index == 5210) {
        *value = m_g92Enabled ? 1 : 0;
        return true;
    }
    if (index >= 5211 && index <= 5219) {
        const int i = index - 5211;
        *value = i < 4 ? length(m_g92Saved[i], i) : 0;
        return true;
    }
    if (index == 5220) {
        *value = m_coord + 1;
        return true;
    }
    if (index >= 5221 && index <= 5390) {
        const int system = (index - 5221) / 20;
        const int i = (index - 5221) % 20;
        *value = i < 4 ? length(m_origin[system][i], i) : i == 9 ? m_rotationDeg[system] : 0;
        return true;
    }
    if (index == 5400) {
        *value = m_tool;
        return true;
    }
    if (index >= 5401 && index <= 5413) {
        // The spindle tool's table entry in machine units (mm), not program units, as
        // LinuxCNC gives them (set_tool_parameters copies the table).
        const ToolEntry e = spindleTool();
        const auto i = static_cast<std::size_t>(index - 5401);
        *value = i < 9     ? e.offsetMm[i]
                 : i == 9  ? e.diameterMm
                 : i == 10 ? e.frontAngle
                 : i == 11 ? e.backAngle
                           : e.orientation;
        return true;
    }
    if (index >= 5420 && index <= 5428) {
        const int i = index - 5420;
        *value = i < 4 ? length(progv[i], i) : 0;
        return true;
    }
    return false;
}

bool Interpreter::systemNamed(std::string_view name, double *value) const
{
    if (name.starts_with("_ini[")) { // LinuxCNC's INI_VARS: #<_ini[section]name>
        const auto it = m_options.iniValues.find(std::string(name.substr(5)));
        if (it == m_options.iniValues.end())
            return false;
        *value = it->second;
        return true;
    }
    const double u = unit();
    const Point4 prog = programPosition();
    struct Entry
    {
        const char *name;
        double value;
    };
    const Entry entries[] = {
        {"_x", prog.x / u},
        {"_y", prog.y / u},
        {"_z", prog.z / u},
        {"_a", prog.a},
        {"_b", 0},
        {"_c", 0},
        {"_u", 0},
        {"_v", 0},
        {"_w", 0},
        {"_line", static_cast<double>(m_line)},
        {"_motion_mode", m_motion / 10.0},
        {"_plane", static_cast<double>(m_plane)},
        {"_metric", m_metric ? 1.0 : 0.0},
        {"_imperial", m_metric ? 0.0 : 1.0},
        {"_absolute", m_absolute ? 1.0 : 0.0},
        {"_incremental", m_absolute ? 0.0 : 1.0},
        {"_ijk_absolute_mode", m_arcAbsolute ? 1.0 : 0.0},
        {"_inverse_time", m_inverseTime ? 1.0 : 0.0},
        {"_units_per_minute", m_inverseTime ? 0.0 : 1.0},
        {"_feed", m_feed},
        {"_rpm", m_speed},
        {"_current_tool", static_cast<double>(m_tool)},
        {"_selected_tool", static_cast<double>(m_selectedTool)},
        {"_coord_system", m_coord < 6 ? 540.0 + 10 * m_coord : 590.0 + (m_coord - 5)},
        {"_spindle_on", m_spindle != 0 ? 1.0 : 0.0},
        {"_spindle_cw", m_spindle == 1 ? 1.0 : 0.0},
        {"_mist", m_mist ? 1.0 : 0.0},
        {"_flood", m_flood ? 1.0 : 0.0},
        {"_retract_r_plane", m_retractToR ? 1.0 : 0.0},
        {"_retract_old_z", m_retractToR ? 0.0 : 1.0},
        {"_value", m_value},
        {"_value_returned", m_valueReturned ? 1.0 : 0.0},
        {"_task", 0.0},
    };
    for (const Entry &e : entries) {
        if (name == e.name) {
            *value = e.value;
            return true;
        }
    }
    return false;
}

} // namespace frezka::gcode
