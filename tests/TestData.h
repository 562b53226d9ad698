#pragma once

#include <QDir>
#include <QString>

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
