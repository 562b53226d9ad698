#include "io/ReferenceSidecar.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

namespace footpath {

namespace {

std::string number(double value)
{
    return QString::number(value).toStdString();
}

void readSidecar(const QString& sidecarPath, Recording& recording)
{
    QFile file(sidecarPath);
    if (!file.open(QIODevice::ReadOnly))
        return;
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(file.readAll(), &parseError);
    const std::string name = sidecarPath.toStdString();
    if (!document.isObject()) {
        recording.warnings.push_back(name + ": byte " + std::to_string(parseError.offset) + ": "
                                     + parseError.errorString().toStdString() + " (reference sidecar ignored)");
        return;
    }
    const QJsonObject root = document.object();
    Reference& reference = recording.reference;
    if (root.contains("closed_loop")) {
        reference.closedLoop = root.value("closed_loop").toBool();
        reference.notes.push_back(std::string(reference.closedLoop ? "closed loop" : "open path") + " from " + name);
    }
    if (root.contains("length_m")) {
        const double length = root.value("length_m").toDouble();
        if (length > 0.0) {
            reference.knownLength_m = length;
            reference.notes.push_back("known length " + number(length) + " m from " + name);
        } else {
            recording.warnings.push_back(name + ": \"length_m\" must be a positive number (ignored)");
        }
    }
}

}  // namespace

double lengthFromFileName(const std::string& path)
{
    static const QRegularExpression pattern(QStringLiteral("(?:^|[_\\-])(\\d+(?:\\.\\d+)?)m(?:[_\\-.]|$)"));
    const QString name = QFileInfo(QString::fromStdString(path)).fileName();
    const QRegularExpressionMatch match = pattern.match(name);
    return match.hasMatch() ? match.captured(1).toDouble() : 0.0;
}

void attachReferenceSidecar(const std::string& recordingPath, Recording& recording)
{
    const double length = lengthFromFileName(recordingPath);
    if (length > 0.0) {
        recording.reference.knownLength_m = length;
        recording.reference.notes.push_back("known length " + number(length) + " m from the file name");
    }
    readSidecar(QString::fromStdString(recordingPath) + ".reference.json", recording);
}

}  // namespace footpath
