#include "io/ColumnNames.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>

namespace footpath {

namespace {

struct Quantity {
    const char* word;
    ColumnRole xRole;  ///< x of a vector quantity, or the role of a scalar one
    bool vector;
};

// Spellings of each quantity, longest first so "accelerometer" is not read as "acc" + "elerometer".
const std::array<Quantity, 24> kQuantities = {{
    {"accelerometer", ColumnRole::AccX, true}, {"acceleration", ColumnRole::AccX, true},
    {"accel", ColumnRole::AccX, true},         {"acc", ColumnRole::AccX, true},
    {"gyroscope", ColumnRole::GyrX, true},     {"angularrate", ColumnRole::GyrX, true},
    {"rateofturn", ColumnRole::GyrX, true},    {"gyro", ColumnRole::GyrX, true},
    {"gyr", ColumnRole::GyrX, true},           {"magnetometer", ColumnRole::MagX, true},
    {"magnetic", ColumnRole::MagX, true},      {"mag", ColumnRole::MagX, true},
    {"a", ColumnRole::AccX, true},             {"w", ColumnRole::GyrX, true},
    {"g", ColumnRole::GyrX, true},             {"m", ColumnRole::MagX, true},
    {"barometer", ColumnRole::Pressure, false}, {"pressure", ColumnRole::Pressure, false},
    {"baro", ColumnRole::Pressure, false},     {"timestamp", ColumnRole::Time, false},
    {"time", ColumnRole::Time, false},         {"t", ColumnRole::Time, false},
    {"packetcounter", ColumnRole::Counter, false}, {"counter", ColumnRole::Counter, false},
}};

/// Lower case, and the unit split off: "Acc X [m/s^2]" -> ("accx", "m/s^2"), "acc_x_mps2" ->
/// ("accx", "mps2") once the unit is known to be a unit.
struct SplitName {
    std::string letters;  ///< the name without separators or the bracketed unit
    std::string unit;     ///< bracketed or trailing unit text, lower case
};

std::string lowerCase(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char ch) { return std::tolower(ch); });
    return text;
}

const std::map<std::string, ColumnMeaning>& unitTokens()
{
    static const std::map<std::string, ColumnMeaning> tokens = [] {
        std::map<std::string, ColumnMeaning> t;
        const auto acc = [](AccUnit u) { ColumnMeaning m; m.accUnit = u; return m; };
        const auto gyr = [](GyrUnit u) { ColumnMeaning m; m.gyrUnit = u; return m; };
        const auto time = [](TimeUnit u) { ColumnMeaning m; m.timeUnit = u; return m; };
        const auto pressure = [](double toPa) { ColumnMeaning m; m.pressureToPa = toPa; return m; };
        for (const char* s : {"mps2", "m/s^2", "m/s2", "ms2", "ms-2", "m/s/s", "m/s²"})
            t[s] = acc(AccUnit::MetresPerSecond2);
        t["g"] = acc(AccUnit::StandardGravity);
        for (const char* s : {"radps", "rad/s", "rads", "rad/sec"})
            t[s] = gyr(GyrUnit::RadiansPerSecond);
        for (const char* s : {"dps", "deg/s", "degps", "degs", "°/s", "deg/sec"})
            t[s] = gyr(GyrUnit::DegreesPerSecond);
        for (const char* s : {"s", "sec", "seconds"})
            t[s] = time(TimeUnit::Seconds);
        t["ms"] = time(TimeUnit::Milliseconds);
        for (const char* s : {"us", "µs", "micros"})
            t[s] = time(TimeUnit::Microseconds);
        t["pa"] = pressure(1.0);
        t["hpa"] = pressure(100.0);
        t["mbar"] = pressure(100.0);
        t["kpa"] = pressure(1000.0);
        return t;
    }();
    return tokens;
}

SplitName splitName(const std::string& raw)
{
    SplitName out;
    std::string name = lowerCase(raw);
    const auto open = name.find_first_of("([");
    if (open != std::string::npos) {
        const auto close = name.find_first_of(")]", open);
        out.unit = name.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1);
        name.erase(open);
    }
    // A trailing "_unit" token: only when it is a known unit, so "acc_x" keeps its "x".
    std::vector<std::string> parts;
    std::string part;
    for (char ch : name) {
        if (ch == '_' || ch == ' ' || ch == '-' || ch == '.') {
            if (!part.empty())
                parts.push_back(part);
            part.clear();
        } else {
            part += ch;
        }
    }
    if (!part.empty())
        parts.push_back(part);
    if (out.unit.empty() && parts.size() > 1 && unitTokens().count(parts.back())) {
        out.unit = parts.back();
        parts.pop_back();
    }
    for (const std::string& p : parts)
        out.letters += p;
    return out;
}

std::optional<ColumnMeaning> withUnit(ColumnMeaning meaning, const std::string& unit)
{
    if (unit.empty())
        return meaning;
    const auto token = unitTokens().find(unit);
    if (token == unitTokens().end())
        return meaning;  // an unknown unit text: the plausibility check decides
    const ColumnMeaning& u = token->second;
    meaning.accUnit = u.accUnit;
    meaning.gyrUnit = u.gyrUnit;
    meaning.timeUnit = u.timeUnit;
    meaning.pressureToPa = u.pressureToPa;
    return meaning;
}

}  // namespace

std::optional<ColumnMeaning> recogniseHeaderName(const std::string& name)
{
    // pyshoe's zero-velocity labels from the motion capture; its zv_shoe_opt etc. are detector
    // outputs, not a reference, and stay skipped.
    if (name == "zv_vicon_opt")
        return ColumnMeaning{ColumnRole::RefStance};
    // A device's node prefix ("inertial-6253.76535:scaledAccelX", MicroStrain SensorConnect) names
    // the sensor, not the quantity; "scaled" says the values are in physical units.
    const std::string quantityName = name.substr(name.find_last_of(':') == std::string::npos ? 0 : name.find_last_of(':') + 1);
    SplitName split = splitName(quantityName);
    if (split.letters.rfind("scaled", 0) == 0)
        split.letters.erase(0, 6);
    const std::string& letters = split.letters;
    for (const Quantity& quantity : kQuantities) {
        const std::string word = quantity.word;
        if (letters.compare(0, word.size(), word) != 0)
            continue;
        const std::string rest = letters.substr(word.size());
        ColumnMeaning meaning;
        if (!quantity.vector) {
            // "t_s" / "time_ms" arrive as letters "ts"/"timems" when the unit was not split off.
            if (!rest.empty() && !unitTokens().count(rest))
                continue;
            meaning.role = quantity.xRole;
            return withUnit(meaning, rest.empty() ? split.unit : rest);
        }
        if (rest.empty() || rest.front() < 'x' || rest.front() > 'z')
            continue;
        const std::string unitAfterAxis = rest.substr(1);
        if (!unitAfterAxis.empty() && !unitTokens().count(unitAfterAxis))
            continue;
        meaning.role = static_cast<ColumnRole>(static_cast<int>(quantity.xRole) + (rest.front() - 'x'));
        return withUnit(meaning, unitAfterAxis.empty() ? split.unit : unitAfterAxis);
    }
    return std::nullopt;
}

const std::vector<std::string>& columnRoleNames()
{
    static const std::vector<std::string> names = {"time_s", "time_ms", "time_us", "counter", "acc_x", "acc_y",
                                                   "acc_z",  "gyr_x",   "gyr_y",   "gyr_z",   "mag_x", "mag_y",
                                                   "mag_z",  "pressure_pa", "pressure_hpa", "pressure_kpa", "skip"};
    return names;
}

std::string listedColumnNames(const std::vector<std::string>& names, ColumnCount count)
{
    constexpr std::size_t kMaxChars = 300;
    std::string listed;
    for (const std::string& name : names)
        listed += (listed.empty() ? "" : ", ") + name;
    if (listed.size() <= kMaxChars)
        return listed;
    // Cut between characters: a byte 10xxxxxx continues a UTF-8 sequence.
    std::size_t cut = kMaxChars;
    while (cut > 0 && (static_cast<unsigned char>(listed[cut]) & 0xC0) == 0x80)
        --cut;
    listed = listed.substr(0, cut) + " ...";
    if (count == ColumnCount::Stated)
        listed += " (" + std::to_string(names.size()) + (names.size() == 1 ? " column)" : " columns)");
    return listed;
}

std::optional<ColumnMeaning> columnMapRole(const std::string& role)
{
    const std::string name = lowerCase(role);
    if (name == "skip")
        return ColumnMeaning{};
    if (std::find(columnRoleNames().begin(), columnRoleNames().end(), name) == columnRoleNames().end())
        return std::nullopt;
    return recogniseHeaderName(name);
}

}  // namespace footpath
