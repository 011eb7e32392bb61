// The profile's list of units on its serial line (key line.units, docs/machine-profile.md
// "Several units on one line"): reading it from JSON, writing it, its rules, and the profiles of
// the other units. Kept apart from machineconfig.cpp because the list is not a key of the schema
// (configschema.h visits single values, not lists of objects).
#include "machine/machineconfig.h"

#include "machine/configschema.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <set>

namespace frezka::machine {

namespace {

inline constexpr schema::Choice<LineUnitRole> kRoles[] = {{"machine", LineUnitRole::Machine},
                                                          {"auxiliary", LineUnitRole::Auxiliary},
                                                          {"rotaryA", LineUnitRole::RotaryA}};

std::string entryKey(std::size_t i)
{
    return "line.units[" + std::to_string(i) + "]";
}

template<class E, std::size_t N>
const char *nameOf(const schema::Choice<E> (&table)[N], E value)
{
    for (const auto &c : table)
        if (c.value == value)
            return c.name;
    return "";
}

template<class E, std::size_t N>
std::string namesOf(const schema::Choice<E> (&table)[N])
{
    std::string text;
    for (const auto &c : table)
        text += (text.empty() ? "\"" : ", \"") + std::string(c.name) + "\"";
    return text;
}

// Reads one entry { address, variant, name, role, profile }; every problem into errors.
LineUnitConfig readEntry(const QJsonValue &value, const std::string &key,
                         std::vector<ConfigError> &errors)
{
    LineUnitConfig u;
    const auto add = [&](ConfigErrorCode code, const std::string &k, const std::string &what) {
        errors.push_back({code, k, k + ": " + what});
    };
    if (!value.isObject()) {
        add(ConfigErrorCode::WrongType, key,
            "must be an object { \"address\": 1, \"variant\": \"gve114\", \"name\": \"...\", "
            "\"role\": \"auxiliary\", \"profile\": \"other.json\" }");
        return u;
    }
    const QJsonObject o = value.toObject();
    for (auto it = o.begin(); it != o.end(); ++it) {
        static const std::set<QString> known{QStringLiteral("address"), QStringLiteral("variant"),
                                             QStringLiteral("name"), QStringLiteral("role"),
                                             QStringLiteral("profile")};
        if (!known.count(it.key()))
            add(ConfigErrorCode::UnknownKey, key + "." + it.key().toStdString(),
                "unknown key; a unit on the line has address, variant, name, role and profile");
    }
    const QJsonValue address = o.value(QLatin1String("address"));
    if (!address.isDouble() || address.toDouble() != address.toInt())
        add(ConfigErrorCode::WrongType, key + ".address", "must be a whole number 0 .. 6");
    else
        u.address = address.toInt();
    const auto choose = [&](const char *k, auto &field, const auto &table) {
        const QJsonValue v = o.value(QLatin1String(k));
        for (const auto &c : table)
            if (v.isString() && v.toString().toStdString() == c.name) {
                field = c.value;
                return;
            }
        add(ConfigErrorCode::BadChoice, key + "." + k, "must be one of " + namesOf(table));
    };
    choose("variant", u.variant, schema::kVariants);
    choose("role", u.role, kRoles);
    const QJsonValue name = o.value(QLatin1String("name"));
    if (!name.isString())
        add(ConfigErrorCode::WrongType, key + ".name",
            "must be a string in double quotes (the name the operator sees)");
    else
        u.name = name.toString().toStdString();
    const QJsonValue profile = o.value(QLatin1String("profile"));
    if (!profile.isUndefined() && !profile.isString())
        add(ConfigErrorCode::WrongType, key + ".profile",
            "must be a string in double quotes: a profile's path, relative to this profile");
    else
        u.profile = profile.toString().toStdString();
    return u;
}

} // namespace

// Takes the key "line" out of the profile's root object (it is not in the schema) and reads it.
void takeLineUnits(QJsonObject &root, MachineConfig &config, std::vector<ConfigError> &errors)
{
    const QJsonValue line = root.take(QLatin1String("line"));
    if (line.isUndefined())
        return;
    const auto add = [&](ConfigErrorCode code, const std::string &k, const std::string &what) {
        errors.push_back({code, k, k + ": " + what});
    };
    if (!line.isObject())
        return add(ConfigErrorCode::WrongType, "line", "must be an object { \"units\": [ ... ] }");
    const QJsonObject o = line.toObject();
    for (auto it = o.begin(); it != o.end(); ++it)
        if (it.key() != QLatin1String("units"))
            add(ConfigErrorCode::UnknownKey, "line." + it.key().toStdString(),
                "unknown key; check its spelling against docs/machine-profile.md or remove it");
    const QJsonValue units = o.value(QLatin1String("units"));
    if (units.isUndefined())
        return;
    if (!units.isArray())
        return add(ConfigErrorCode::WrongType, "line.units",
                   "must be a list [ { ... }, { ... } ] of the units on the line");
    const QJsonArray list = units.toArray();
    config.line.units.clear();
    for (qsizetype i = 0; i < list.size(); ++i)
        config.line.units.push_back(readEntry(list.at(i), entryKey(std::size_t(i)), errors));
}

// The "line" object as the writer puts it after the schema's keys; empty when there is none.
std::string lineUnitsJson(const MachineConfig &config)
{
    if (config.line.units.empty())
        return {};
    const auto quoted = [](const std::string &text) {
        const QByteArray q =
            QJsonDocument(QJsonArray{QString::fromStdString(text)}).toJson(QJsonDocument::Compact);
        return q.mid(1, q.size() - 2).toStdString();
    };
    std::string out = ",\n    \"line\": {\n        \"units\": [";
    for (std::size_t i = 0; i < config.line.units.size(); ++i) {
        const LineUnitConfig &u = config.line.units[i];
        out += std::string(i ? "," : "") +
               "\n            {\"address\": " + std::to_string(u.address) + ", \"variant\": \"" +
               nameOf(schema::kVariants, u.variant) + "\", \"name\": " + quoted(u.name) +
               ", \"role\": \"" + nameOf(kRoles, u.role) + "\"";
        if (!u.profile.empty())
            out += ", \"profile\": " + quoted(u.profile);
        out += "}";
    }
    return out + "\n        ]\n    }";
}

// The list's rules (validateMachineConfig and the reader): addresses, variants, roles.
std::vector<ConfigError> lineUnitsProblems(const MachineConfig &c)
{
    std::vector<ConfigError> errors;
    const auto fail = [&](const std::string &key, const std::string &what) {
        errors.push_back({ConfigErrorCode::Inconsistent, key, key + ": " + what});
    };
    const auto &units = c.line.units;
    std::set<int> seen;
    int machines = 0, rotaries = 0;
    for (std::size_t i = 0; i < units.size(); ++i) {
        const LineUnitConfig &u = units[i];
        const std::string key = entryKey(i);
        if (u.address == 7)
            fail(key + ".address", "is 7, the spindle's address; give the unit its own "
                                   "address 0 .. 6 (as ordered)");
        else if (u.address < 0 || u.address > 6)
            fail(key + ".address", "is " + std::to_string(u.address) + ", must be 0 .. 6");
        else if (!seen.insert(u.address).second)
            fail(key + ".address", "address " + std::to_string(u.address) +
                                       " is used twice on the line; each unit has its own");
        if (units.size() > 1 && u.variant != protocol::Variant::Gve114)
            fail(key + ".variant", "only GVE114 units share a line (addressable units, GVE114 "
                                   "manual §9.5); connect this unit to a port of its own");
        if (u.name.empty())
            fail(key + ".name", "is empty; name the unit as the operator knows it");
        machines += u.role == LineUnitRole::Machine;
        rotaries += u.role == LineUnitRole::RotaryA;
        if (u.role == LineUnitRole::Machine && !u.profile.empty())
            fail(key + ".profile", "the machine's unit is this profile's; remove the key");
        if (u.role == LineUnitRole::Auxiliary && u.profile.empty())
            fail(key + ".profile", "an auxiliary unit needs its own profile (its axes and "
                                   "scales): give its path, relative to this profile");
        if (u.role == LineUnitRole::Machine &&
            (u.address != c.unit.address || u.variant != c.unit.variant))
            fail(key, "the machine's unit must be the one of unit.address and unit.variant; "
                      "make them the same");
    }
    if (!units.empty() && machines != 1)
        fail("line.units", "has " + std::to_string(machines) +
                               " units with the role \"machine\"; exactly one must have it (the "
                               "unit of this profile's machine)");
    if (rotaries > 1)
        fail("line.units", "has more than one unit with the role \"rotaryA\"; a program has one "
                           "A axis");
    return errors;
}

int machineUnitIndex(const MachineConfig &config)
{
    for (std::size_t i = 0; i < config.line.units.size(); ++i)
        if (config.line.units[i].role == LineUnitRole::Machine)
            return int(i);
    return 0;
}

LineProfiles loadLineProfiles(const MachineConfig &config, const std::string &profilePath)
{
    LineProfiles out;
    if (config.line.units.empty()) {
        out.configs.push_back(config);
        return out;
    }
    const QDir base = QFileInfo(QString::fromStdString(profilePath)).absoluteDir();
    for (std::size_t i = 0; i < config.line.units.size(); ++i) {
        const LineUnitConfig &u = config.line.units[i];
        const std::string key = entryKey(i) + ".profile";
        if (u.role == LineUnitRole::Machine) {
            out.configs.push_back(config);
            continue;
        }
        MachineConfig unit = defaultMachineConfig(protocol::Variant::Gve114);
        unit.name = u.name;
        if (!u.profile.empty()) {
            const QString file = QString::fromStdString(u.profile);
            const std::string path = QDir::isAbsolutePath(file) || profilePath.empty()
                                         ? file.toStdString()
                                         : QDir::cleanPath(base.filePath(file)).toStdString();
            const ConfigResult r = loadMachineConfig(path);
            for (const ConfigError &e : r.errors)
                out.errors.push_back({e.code, key, key + ": " + e.message});
            if (!r.config)
                continue;
            unit = *r.config;
            if (unit.unit.variant != u.variant)
                out.errors.push_back({ConfigErrorCode::Inconsistent, key,
                                      key + ": " + path +
                                          " is the profile of another unit type than the entry "
                                          "says (unit.variant); make them the same"});
        }
        unit.unit.address = u.address;
        unit.link = config.link; // one line: its port and baud rate
        out.configs.push_back(std::move(unit));
    }
    if (!out.errors.empty())
        out.configs.clear();
    return out;
}

} // namespace frezka::machine
