// Machine profile JSON: reading (with validation), writing, range checks. The keys and ranges
// live once in configschema.h; cross-key rules in configrules.cpp.
#include "machine/machineconfig.h"

#include "machine/configschema.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>

namespace frezka::machine {

std::vector<ConfigError> checkConsistency(const MachineConfig &config); // configrules.cpp
// lineunits.cpp: the key "line" (a list, outside the schema).
void takeLineUnits(QJsonObject &root, MachineConfig &config, std::vector<ConfigError> &errors);
std::string lineUnitsJson(const MachineConfig &config);

namespace {

std::string fmt(double v)
{
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

std::string rangeText(double min, double max, const char *unit)
{
    std::string text = fmt(min) + " .. " + fmt(max);
    if (unit && *unit)
        text += std::string(" ") + unit;
    return text;
}

template<class E>
std::string choiceList(std::span<const schema::Choice<E>> choices)
{
    std::string text;
    for (const auto &c : choices)
        text += (text.empty() ? "\"" : ", \"") + std::string(c.name) + "\"";
    return text;
}

std::string hexByte(std::uint8_t b)
{
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02X", b);
    return buf;
}

// Reads one JSON object into the config, checking types and ranges; unknown keys are errors.
class Reader
{
public:
    Reader(const QJsonObject &object, std::string path, std::vector<ConfigError> &errors)
        : m_object(object)
        , m_path(std::move(path))
        , m_errors(errors)
    {}

    ~Reader()
    {
        for (auto it = m_object.begin(); it != m_object.end(); ++it) {
            const std::string key = it.key().toStdString();
            if (!m_known.count(key))
                add(ConfigErrorCode::UnknownKey, key,
                    "unknown key; check its spelling against docs/machine-profile.md or remove it");
        }
    }

    void number(const char *key, double &v, double min, double max, const char *unit)
    {
        const QJsonValue j = take(key);
        if (j.isUndefined())
            return;
        if (!j.isDouble())
            return add(ConfigErrorCode::WrongType, key,
                       "must be a number (" + rangeText(min, max, unit) + ")");
        const double x = j.toDouble();
        if (!(x >= min && x <= max))
            return add(ConfigErrorCode::OutOfRange, key,
                       "is " + fmt(x) + ", must be " + rangeText(min, max, unit));
        v = x;
    }

    void integer(const char *key, int &v, int min, int max, const char *unit)
    {
        const QJsonValue j = take(key);
        if (j.isUndefined())
            return;
        const double x = j.toDouble(std::nan(""));
        if (!j.isDouble() || x != std::floor(x))
            return add(ConfigErrorCode::WrongType, key,
                       "must be a whole number (" + rangeText(min, max, unit) + ")");
        if (x < min || x > max)
            return add(ConfigErrorCode::OutOfRange, key,
                       "is " + fmt(x) + ", must be " + rangeText(min, max, unit));
        v = static_cast<int>(x);
    }

    void boolean(const char *key, bool &v)
    {
        const QJsonValue j = take(key);
        if (j.isUndefined())
            return;
        if (!j.isBool())
            return add(ConfigErrorCode::WrongType, key, "must be true or false");
        v = j.toBool();
    }

    void text(const char *key, std::string &v)
    {
        const QJsonValue j = take(key);
        if (j.isUndefined())
            return;
        if (!j.isString())
            return add(ConfigErrorCode::WrongType, key, "must be a string in double quotes");
        v = j.toString().toStdString();
    }

    void byte(const char *key, std::uint8_t &v)
    {
        const QJsonValue j = take(key);
        if (j.isUndefined())
            return;
        bool ok = false;
        int x = -1;
        if (j.isString()) {
            QString s = j.toString();
            if (s.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
                s = s.mid(2);
            x = s.toInt(&ok, 16);
            ok = ok && s.size() <= 2;
        } else if (j.isDouble()) {
            x = j.toInt(-1);
            ok = x >= 0 && x == j.toDouble();
        }
        if (!ok || x < 0 || x > 255)
            return add(ConfigErrorCode::OutOfRange, key,
                       "must be a byte: a hex string \"0x00\" .. \"0xFF\" or a number 0 .. 255");
        v = static_cast<std::uint8_t>(x);
    }

    template<class E>
    void choice(const char *key, E &v, std::span<const schema::Choice<E>> choices)
    {
        const QJsonValue j = take(key);
        if (j.isUndefined())
            return;
        const std::string s = j.toString().toStdString();
        for (const auto &c : choices) {
            if (j.isString() && s == c.name) {
                v = c.value;
                return;
            }
        }
        add(ConfigErrorCode::BadChoice, key, "must be one of " + choiceList(choices));
    }

    template<class F>
    void object(const char *key, F &&fn)
    {
        const QJsonValue j = take(key);
        if (j.isUndefined())
            return;
        if (!j.isObject())
            return add(ConfigErrorCode::WrongType, key, "must be an object { ... }");
        Reader sub(j.toObject(), join(key), m_errors);
        fn(sub);
    }

private:
    QJsonValue take(const char *key)
    {
        m_known.insert(key);
        return m_object.value(QLatin1String(key));
    }
    std::string join(const std::string &key) const
    {
        return m_path.empty() ? key : m_path + "." + key;
    }
    void add(ConfigErrorCode code, const std::string &key, const std::string &what)
    {
        m_errors.push_back({code, join(key), join(key) + ": " + what});
    }

    QJsonObject m_object;
    std::string m_path;
    std::vector<ConfigError> &m_errors;
    std::set<std::string> m_known;
};

// Writes the profile as ordered, indented JSON (the order of the schema, not alphabetical).
class Writer
{
public:
    explicit Writer(std::string &out, int depth = 1)
        : m_out(out)
        , m_depth(depth)
    {}

    void number(const char *key, double &v, double, double, const char *) { put(key, fmt(v)); }
    void integer(const char *key, int &v, int, int, const char *) { put(key, std::to_string(v)); }
    void boolean(const char *key, bool &v) { put(key, v ? "true" : "false"); }
    void text(const char *key, std::string &v)
    {
        const QByteArray quoted =
            QJsonDocument(QJsonArray{QString::fromStdString(v)}).toJson(QJsonDocument::Compact);
        put(key, quoted.mid(1, quoted.size() - 2).toStdString());
    }
    void byte(const char *key, std::uint8_t &v) { put(key, "\"" + hexByte(v) + "\""); }
    template<class E>
    void choice(const char *key, E &v, std::span<const schema::Choice<E>> choices)
    {
        for (const auto &c : choices) {
            if (c.value == v)
                return put(key, std::string("\"") + c.name + "\"");
        }
    }
    template<class F>
    void object(const char *key, F &&fn)
    {
        put(key, "{\n");
        Writer sub(m_out, m_depth + 1);
        fn(sub);
        m_out += "\n" + indent(m_depth) + "}";
    }

private:
    static std::string indent(int depth)
    {
        return std::string(static_cast<std::size_t>(depth) * 4, ' ');
    }
    void put(const char *key, const std::string &value)
    {
        m_out += (m_first ? "" : ",\n") + indent(m_depth) + "\"" + key + "\": " + value;
        m_first = false;
    }

    std::string &m_out;
    int m_depth;
    bool m_first = true;
};

// Checks that values built in code lie in the schema's ranges (the reader checks files).
class RangeChecker
{
public:
    RangeChecker(std::vector<ConfigError> &errors, std::string path = {})
        : m_errors(errors)
        , m_path(std::move(path))
    {}
    void number(const char *key, double &v, double min, double max, const char *unit)
    {
        if (!(v >= min && v <= max))
            add(key, "is " + fmt(v) + ", must be " + rangeText(min, max, unit));
    }
    void integer(const char *key, int &v, int min, int max, const char *unit)
    {
        if (v < min || v > max)
            add(key, "is " + std::to_string(v) + ", must be " + rangeText(min, max, unit));
    }
    void boolean(const char *, bool &) {}
    void text(const char *, std::string &) {}
    void byte(const char *, std::uint8_t &) {}
    template<class E>
    void choice(const char *key, E &v, std::span<const schema::Choice<E>> choices)
    {
        for (const auto &c : choices) {
            if (c.value == v)
                return;
        }
        add(key, "must be one of " + choiceList(choices));
    }
    template<class F>
    void object(const char *key, F &&fn)
    {
        RangeChecker sub(m_errors, join(key));
        fn(sub);
    }

private:
    std::string join(const std::string &key) const
    {
        return m_path.empty() ? key : m_path + "." + key;
    }
    void add(const char *key, const std::string &what)
    {
        m_errors.push_back({ConfigErrorCode::OutOfRange, join(key), join(key) + ": " + what});
    }
    std::vector<ConfigError> &m_errors;
    std::string m_path;
};

void lineAndColumn(const std::string &text, int offset, int &line, int &column)
{
    line = 1;
    column = 1;
    for (int i = 0; i < offset && i < static_cast<int>(text.size()); ++i) {
        if (text[static_cast<std::size_t>(i)] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
}

// Keys of older profiles: each is taken out of the object before it is read, and a note says
// what became of it. eeprom.stepPolarityInvert meant the opposite physical edge on a GVE114
// than on a GVE64, so it becomes the edge it selected on the profile's own variant.
void takeRetiredKeys(QJsonObject &root, protocol::Variant variant, MachineConfig &config,
                     std::vector<ConfigError> &notes)
{
    const auto take = [&](const char *object, const char *key) {
        QJsonObject o = root.value(QLatin1String(object)).toObject();
        const QJsonValue v = o.take(QLatin1String(key));
        if (!v.isUndefined())
            root.insert(QLatin1String(object), o);
        return v;
    };
    if (!take("link", "packetCommands").isUndefined())
        notes.push_back({ConfigErrorCode::Retired, "link.packetCommands",
                         "link.packetCommands: retired and ignored: the driver fills each "
                         "packet up to the unit's byte limit; remove the key"});
    const QJsonValue invert = take("eeprom", "stepPolarityInvert");
    if (invert.isUndefined())
        return;
    const bool is114 = variant == protocol::Variant::Gve114;
    const bool on = invert.toBool();
    if (on)
        config.eeprom.stepEdge = is114 ? StepEdge::Falling : StepEdge::Rising;
    notes.push_back({ConfigErrorCode::Retired, "eeprom.stepPolarityInvert",
                     std::string("eeprom.stepPolarityInvert: retired; read as stepActiveEdge \"") +
                         (!on     ? "default"
                          : is114 ? "falling"
                                  : "rising") +
                         "\"; save the profile or write that key instead"});
}

} // namespace

ConfigResult parseMachineConfig(const std::string &json)
{
    ConfigResult result;
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(json), &parseError);
    if (parseError.error != QJsonParseError::NoError || !doc.isObject()) {
        int line = 1, column = 1;
        lineAndColumn(json, parseError.offset, line, column);
        const std::string what = parseError.error != QJsonParseError::NoError
                                     ? parseError.errorString().toStdString()
                                     : std::string("the profile must be one JSON object { ... }");
        result.errors.push_back({ConfigErrorCode::Syntax,
                                 {},
                                 "line " + std::to_string(line) + ", column " +
                                     std::to_string(column) + ": " + what +
                                     "; fix the JSON syntax there"});
        return result;
    }
    // The variant decides the defaults of every key the file leaves out.
    MachineConfig config;
    protocol::Variant variant = protocol::Variant::Gve64;
    {
        std::vector<ConfigError> ignored;
        const QJsonObject unit = doc.object().value(QLatin1String("unit")).toObject();
        Reader r(QJsonObject{{QStringLiteral("variant"), unit.value(QLatin1String("variant"))}}, {},
                 ignored);
        r.choice("variant", variant, schema::all(schema::kVariants));
    }
    config = defaultMachineConfig(variant);
    QJsonObject root = doc.object();
    takeRetiredKeys(root, variant, config, result.notes);
    takeLineUnits(root, config, result.errors);
    {
        Reader reader(root, {}, result.errors);
        schema::visitProfile(reader, config);
    }
    if (result.errors.empty())
        result.errors = checkConsistency(config);
    if (result.errors.empty())
        result.config = config;
    return result;
}

ConfigResult loadMachineConfig(const std::string &path)
{
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly)) {
        ConfigResult result;
        result.errors.push_back({ConfigErrorCode::FileUnreadable,
                                 {},
                                 path + ": cannot read the machine profile (" +
                                     file.errorString().toStdString() +
                                     "); check the path and its permissions"});
        return result;
    }
    ConfigResult result = parseMachineConfig(file.readAll().toStdString());
    for (ConfigError &e : result.errors)
        e.message = path + ": " + e.message;
    for (ConfigError &e : result.notes)
        e.message = path + ": " + e.message;
    return result;
}

std::vector<ConfigError> validateMachineConfig(const MachineConfig &config)
{
    std::vector<ConfigError> errors;
    MachineConfig copy = config;
    RangeChecker checker(errors);
    schema::visitProfile(checker, copy);
    if (errors.empty())
        errors = checkConsistency(config);
    return errors;
}

std::string toJson(const MachineConfig &config)
{
    std::string out = "{\n";
    MachineConfig copy = config;
    {
        Writer writer(out);
        schema::visitProfile(writer, copy);
    }
    out += lineUnitsJson(config) + "\n}\n";
    return out;
}

std::optional<ConfigError> saveMachineConfig(const MachineConfig &config, const std::string &path)
{
    QFile file(QString::fromStdString(path));
    const std::string text = toJson(config);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
        file.write(text.data(), static_cast<qint64>(text.size())) !=
            static_cast<qint64>(text.size())) {
        return ConfigError{ConfigErrorCode::FileUnreadable,
                           {},
                           path + ": cannot write the machine profile (" +
                               file.errorString().toStdString() +
                               "); check the path and its permissions"};
    }
    return std::nullopt;
}

} // namespace frezka::machine
