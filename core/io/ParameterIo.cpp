#include "io/ParameterIo.h"

#include "io/NearestNames.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

namespace footpath {

namespace {

constexpr const char* kFormat = "footpath-parameters";
constexpr int kVersion = 1;

std::string applyValue(Parameters& params, const ParameterField& field, const QJsonValue& value)
{
    if (field.kind == ParameterField::Kind::Choice) {
        if (!value.isString())
            return std::string("'") + field.name + "' must be a name";
        return setParameter(params, field.name, value.toString().toStdString());
    }
    if (field.kind == ParameterField::Kind::Flag) {
        if (!value.isBool())
            return std::string("'") + field.name + "' must be true or false";
        params.*field.flag = value.toBool();
        return {};
    }
    if (!value.isDouble())
        return std::string("'") + field.name + "' must be a number";
    params.*field.real = value.toDouble();
    return {};
}

std::vector<std::string> parameterNames()
{
    std::vector<std::string> names;
    for (const ParameterField& field : parameterFields())
        names.emplace_back(field.name);
    return names;
}

}  // namespace

std::vector<std::string> nearestParameterNames(const std::string& name)
{
    return nearestNames(name, parameterNames());
}

std::string setParameterByName(Parameters& params, const std::string& name, const std::string& text)
{
    std::string problem = setParameter(params, name, text);
    if (!problem.empty() && !findParameterField(name))
        problem += didYouMean(name, parameterNames());
    return problem;
}

std::string parametersToJson(const Parameters& params)
{
    QJsonObject values;
    for (const ParameterField& field : parameterFields()) {
        if (field.kind == ParameterField::Kind::Choice)
            values.insert(QString::fromUtf8(field.name), QString::fromStdString(choiceName(params, field)));
        else if (field.kind == ParameterField::Kind::Flag)
            values.insert(QString::fromUtf8(field.name), params.*field.flag);
        else
            values.insert(QString::fromUtf8(field.name), params.*field.real);
    }
    QJsonObject root{{"format", kFormat}, {"version", kVersion}, {"parameters", values}};
    return QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString();
}

std::string parametersFromJson(const std::string& json, const std::string& sourceName, Parameters& params)
{
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(QByteArray::fromStdString(json), &parseError);
    if (document.isNull())
        return sourceName + ": byte " + std::to_string(parseError.offset) + ": "
               + parseError.errorString().toStdString();
    const QJsonObject root = document.object();
    if (root.value("format").toString() != kFormat)
        return sourceName + ": expected \"format\": \"" + kFormat + "\"";
    if (root.value("version").toInt() > kVersion)
        return sourceName + ": preset version " + std::to_string(root.value("version").toInt())
               + " is newer than this Footpath understands (" + std::to_string(kVersion) + ")";
    const QJsonObject values = root.value("parameters").toObject();
    Parameters updated = params;
    for (auto it = values.begin(); it != values.end(); ++it) {
        const ParameterField* field = findParameterField(it.key().toStdString());
        if (!field)
            return sourceName + ": unknown parameter '" + it.key().toStdString() + "'"
                   + didYouMean(it.key().toStdString(), parameterNames());
        if (std::string problem = applyValue(updated, *field, it.value()); !problem.empty())
            return sourceName + ": " + problem;
    }
    params = updated;
    return {};
}

std::string loadParameters(const std::string& path, Parameters& params)
{
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly))
        return path + ": cannot open the preset: " + file.errorString().toStdString();
    return parametersFromJson(file.readAll().toStdString(), path, params);
}

std::string saveParameters(const std::string& path, const Parameters& params)
{
    // QSaveFile writes to a temporary file and renames it: a crash never leaves half a preset.
    QSaveFile file(QString::fromStdString(path));
    const std::string json = parametersToJson(params);
    if (!file.open(QIODevice::WriteOnly) || file.write(json.data(), static_cast<qint64>(json.size())) < 0
        || !file.commit())
        return path + ": cannot write the preset: " + file.errorString().toStdString();
    return {};
}

}  // namespace footpath
