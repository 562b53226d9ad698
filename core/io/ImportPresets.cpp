#include "io/ImportPresets.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QStandardPaths>

namespace footpath {

namespace {

constexpr const char* kFormat = "footpath-import-preset";
constexpr int kVersion = 1;

template <typename Unit>
struct UnitSpelling {
    const char* text;
    Unit unit;
};

const UnitSpelling<AccUnit> kAccUnits[] = {{"mps2", AccUnit::MetresPerSecond2}, {"g", AccUnit::StandardGravity}};
const UnitSpelling<GyrUnit> kGyrUnits[] = {{"radps", GyrUnit::RadiansPerSecond}, {"degps", GyrUnit::DegreesPerSecond}};
const UnitSpelling<TimeUnit> kTimeUnits[] = {
    {"s", TimeUnit::Seconds}, {"ms", TimeUnit::Milliseconds}, {"us", TimeUnit::Microseconds}};

template <typename Unit, std::size_t N>
bool parseUnit(const UnitSpelling<Unit> (&table)[N], const std::string& text, Unit& unit)
{
    for (const auto& entry : table)
        if (text == entry.text) {
            unit = entry.unit;
            return true;
        }
    return false;
}

template <typename Unit, std::size_t N>
QString spell(const UnitSpelling<Unit> (&table)[N], Unit unit)
{
    for (const auto& entry : table)
        if (entry.unit == unit)
            return QString::fromUtf8(entry.text);
    return {};
}

bool validName(const std::string& name)
{
    return !name.empty() && name.find_first_of("/\\:") == std::string::npos && name.front() != '.';
}

/// "rate_hz" is optional; 0 says "from the file", as it does in ImportOptions.
std::string readRate(const QJsonObject& root, const std::string& sourceName, double& rate_hz)
{
    rate_hz = 0.0;
    if (!root.contains("rate_hz"))
        return {};
    const QJsonValue value = root.value("rate_hz");
    if (value.isDouble() && value.toDouble() >= 0.0 && value.toDouble() <= kMaxImportRate_hz) {
        rate_hz = value.toDouble();
        return {};
    }
    const QString given = value.isDouble() ? QString::number(value.toDouble(), 'g', 10)
                                           : QString::fromUtf8(QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact))
                                                 .mid(1).chopped(1);
    return sourceName + ": \"rate_hz\" must be a number of Hz from 0 (the rate comes from the file) to "
           + QString::number(kMaxImportRate_hz).toStdString() + ", got " + given.toStdString();
}

}  // namespace

bool parseAccUnit(const std::string& text, AccUnit& unit) { return parseUnit(kAccUnits, text, unit); }
bool parseGyrUnit(const std::string& text, GyrUnit& unit) { return parseUnit(kGyrUnits, text, unit); }
bool parseTimeUnit(const std::string& text, TimeUnit& unit) { return parseUnit(kTimeUnits, text, unit); }

std::string importPresetToJson(const ImportPreset& preset)
{
    QJsonArray columns;
    for (const std::string& role : preset.columnMap)
        columns.append(QString::fromStdString(role));
    QJsonObject root{{"format", kFormat}, {"version", kVersion}, {"name", QString::fromStdString(preset.name)}};
    if (!preset.format.empty())
        root.insert("file_format", QString::fromStdString(preset.format));
    if (!columns.isEmpty())
        root.insert("columns", columns);
    if (preset.accUnit != AccUnit::Unknown)
        root.insert("acc_unit", spell(kAccUnits, preset.accUnit));
    if (preset.gyrUnit != GyrUnit::Unknown)
        root.insert("gyr_unit", spell(kGyrUnits, preset.gyrUnit));
    if (preset.timeUnit != TimeUnit::Unknown)
        root.insert("time_unit", spell(kTimeUnits, preset.timeUnit));
    if (preset.rate_hz > 0.0)
        root.insert("rate_hz", preset.rate_hz);
    return QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString();
}

std::string importPresetFromJson(const std::string& json, const std::string& sourceName, ImportPreset& preset)
{
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(QByteArray::fromStdString(json), &parseError);
    if (!document.isObject())
        return sourceName + ": byte " + std::to_string(parseError.offset) + ": " + parseError.errorString().toStdString();
    const QJsonObject root = document.object();
    if (root.value("format").toString() != kFormat)
        return sourceName + ": expected \"format\": \"" + kFormat + "\"";
    ImportPreset read;
    read.name = root.value("name").toString().toStdString();
    read.format = root.value("file_format").toString().toStdString();
    for (const QJsonValue& role : root.value("columns").toArray())
        read.columnMap.push_back(role.toString().toStdString());
    const auto unitText = [&root](const char* key) { return root.value(key).toString().toStdString(); };
    if (root.contains("acc_unit") && !parseAccUnit(unitText("acc_unit"), read.accUnit))
        return sourceName + ": \"acc_unit\" must be mps2 or g";
    if (root.contains("gyr_unit") && !parseGyrUnit(unitText("gyr_unit"), read.gyrUnit))
        return sourceName + ": \"gyr_unit\" must be radps or degps";
    if (root.contains("time_unit") && !parseTimeUnit(unitText("time_unit"), read.timeUnit))
        return sourceName + ": \"time_unit\" must be s, ms or us";
    if (std::string problem = readRate(root, sourceName, read.rate_hz); !problem.empty())
        return problem;
    preset = read;
    return {};
}

std::string importPresetDirectory()
{
    const QByteArray fromEnv = qgetenv("FOOTPATH_IMPORT_PRESETS");
    if (!fromEnv.isEmpty())
        return fromEnv.toStdString();
    return (QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation) + "/footpath/import-presets")
        .toStdString();
}

std::string saveImportPreset(const ImportPreset& preset, const std::string& directory)
{
    if (!validName(preset.name))
        return "an import preset needs a name without '/', '\\' or ':' (got '" + preset.name + "')";
    if (!QDir().mkpath(QString::fromStdString(directory)))
        return directory + ": cannot create the preset folder";
    const QString path = QDir(QString::fromStdString(directory)).filePath(QString::fromStdString(preset.name) + ".json");
    QSaveFile file(path);
    const std::string json = importPresetToJson(preset);
    if (!file.open(QIODevice::WriteOnly) || file.write(json.data(), static_cast<qint64>(json.size())) < 0
        || !file.commit())
        return path.toStdString() + ": cannot write the preset: " + file.errorString().toStdString();
    return {};
}

std::string loadImportPreset(const std::string& nameOrPath, ImportPreset& preset, const std::string& directory)
{
    QString path = QString::fromStdString(nameOrPath);
    if (!QFileInfo::exists(path))
        path = QDir(QString::fromStdString(directory)).filePath(path + ".json");
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        std::string known;
        for (const ImportPreset& saved : listImportPresets(directory))
            known += (known.empty() ? "" : ", ") + saved.name;
        return "no import preset '" + nameOrPath + "' (looked for " + path.toStdString() + "); saved presets: "
               + (known.empty() ? std::string("none") : known);
    }
    return importPresetFromJson(file.readAll().toStdString(), path.toStdString(), preset);
}

std::vector<ImportPreset> listImportPresets(const std::string& directory)
{
    std::vector<ImportPreset> presets;
    const QDir dir(QString::fromStdString(directory));
    for (const QString& name : dir.entryList({"*.json"}, QDir::Files, QDir::Name)) {
        QFile file(dir.filePath(name));
        ImportPreset preset;
        if (file.open(QIODevice::ReadOnly)
            && importPresetFromJson(file.readAll().toStdString(), name.toStdString(), preset).empty())
            presets.push_back(preset);
    }
    return presets;
}

void applyImportPreset(const ImportPreset& preset, ImportOptions& options)
{
    if (options.format.empty())
        options.format = preset.format;
    if (options.columnMap.empty())
        options.columnMap = preset.columnMap;
    if (options.accUnit == AccUnit::Unknown)
        options.accUnit = preset.accUnit;
    if (options.gyrUnit == GyrUnit::Unknown)
        options.gyrUnit = preset.gyrUnit;
    if (options.timeUnit == TimeUnit::Unknown)
        options.timeUnit = preset.timeUnit;
    if (options.rate_hz <= 0.0)
        options.rate_hz = preset.rate_hz;
}

}  // namespace footpath
