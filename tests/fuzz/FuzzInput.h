#pragma once

// Small helpers shared by the libFuzzer targets: the fuzzer's bytes as text or a stream, and a
// scratch directory for readers that take a path (sidecars next to a recording).

#include "io/Import.h"
#include "nav/InputCheck.h"

#include <QDir>
#include <QFile>
#include <QString>
#include <QCoreApplication>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

namespace footpath::fuzz {

inline std::string asText(const std::uint8_t* data, std::size_t size)
{
    return std::string(reinterpret_cast<const char*>(data), size);
}

/// A directory of this process's own under $TMPDIR, made once (fuzzers run single-threaded) and
/// removed when the fuzzer exits normally; after a crash it stays, with the input beside it.
inline const QString& scratchDirectory()
{
    struct Scratch {
        QString path = QDir::temp().filePath(
            QStringLiteral("footpath-fuzz-%1").arg(QCoreApplication::applicationPid()));
        Scratch() { QDir().mkpath(path); }
        ~Scratch() { QDir(path).removeRecursively(); }
    };
    static const Scratch scratch;
    return scratch.path;
}

/// Overwrites `fileName` in the scratch directory with the bytes; returns its path.
inline QString writeScratchFile(const QString& fileName, const std::uint8_t* data, std::size_t size)
{
    const QString path = QDir(scratchDirectory()).filePath(fileName);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        std::abort();  // the harness itself is broken, not the reader under test
    file.write(reinterpret_cast<const char*>(data), static_cast<qint64>(size));
    return path;
}

/// A reader's promise: what it returns as read can be estimated (finite values, time never going
/// back), so the pipeline never meets a NaN it did not cause. A broken promise is a finding.
inline void checkImported(const ImportResult& result)
{
    if (result.ok() && !describeUnusableSamples(result.recording.samples).empty())
        std::abort();
}

/// Reads the bytes as a file of the given format (as `--format` forces it) and checks the result.
inline void importAs(const std::uint8_t* data, std::size_t size, const char* format, const char* name)
{
    std::istringstream in(asText(data, size));
    ImportOptions options;
    options.format = format;
    checkImported(importStream(in, size, name, options));
}

}  // namespace footpath::fuzz
