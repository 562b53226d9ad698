#pragma once

#include <QDir>
#include <QFile>
#include <QString>
#include <QTemporaryDir>

// Real recordings live beside the project in ../shared/datasets (CI always has them; a user's
// clone usually does not, so tests that need them QSKIP with this message).
inline QString datasetsDir()
{
    const QByteArray fromEnv = qgetenv("FOOTPATH_DATASETS");
    return fromEnv.isEmpty() ? QString::fromUtf8(FOOTPATH_DATASETS_DIR) : QString::fromLocal8Bit(fromEnv);
}

inline QString datasetPath(const QString& relative)
{
    return QDir(datasetsDir()).filePath(relative);
}

#define FOOTPATH_REQUIRE_DATASETS()                                                              \
    do {                                                                                         \
        if (!QDir(datasetsDir()).exists())                                                       \
            QSKIP(qPrintable(QStringLiteral("shared datasets not found at %1 (set FOOTPATH_DATASETS)") \
                                 .arg(datasetsDir())));                                          \
    } while (false)

/// Writes content to a file named name in dir; its path, or empty when it could not be written.
inline QString writeFileIn(const QTemporaryDir& dir, const QString& name, const QByteArray& content)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(content) != content.size())
        return {};
    return path;
}
