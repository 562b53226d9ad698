#pragma once

// Running footpath-cli (FOOTPATH_CLI) as a process from a test, and writing the simulated walks it
// reads. Shared by the CLI tests.

#include "Recording.h"

#include <QByteArray>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QtTest>

#include <cstdio>
#include <vector>

#ifndef FOOTPATH_CLI
#error "FOOTPATH_CLI must name the footpath-cli binary"
#endif

namespace clitest {

constexpr int kTimeoutMs = 300000;
constexpr int kExitBadInput = 2;

struct Run {
    bool finished = false;
    QProcess::ExitStatus status = QProcess::CrashExit;
    int exitCode = -1;
    QString out;
    QString err;

    QByteArray describe() const
    {
        return QStringLiteral("exit %1 (%2)\nstdout: %3\nstderr: %4")
            .arg(exitCode)
            .arg(QLatin1String(finished ? (status == QProcess::NormalExit ? "normal" : "crashed") : "timed out"))
            .arg(out, err)
            .toLocal8Bit();
    }
};

inline Run runCli(const QStringList& args, const QString& workingDirectory = {})
{
    QProcess process;
    process.setProgram(QString::fromUtf8(FOOTPATH_CLI));
    process.setArguments(args);
    if (!workingDirectory.isEmpty())
        process.setWorkingDirectory(workingDirectory);
    process.start();
    Run run;
    run.finished = process.waitForStarted(kTimeoutMs) && process.waitForFinished(kTimeoutMs);
    if (!run.finished)
        process.kill();
    run.status = process.exitStatus();
    run.exitCode = process.exitCode();
    run.out = QString::fromLocal8Bit(process.readAllStandardOutput());
    run.err = QString::fromLocal8Bit(process.readAllStandardError());
    return run;
}

/// Enough digits that the CLI reads back the simulated value.
inline QByteArray number(double value)
{
    char buffer[40];
    const int length = std::snprintf(buffer, sizeof buffer, "%.10g", value);
    return QByteArray(buffer, length);
}

/// The samples as the delimited reader takes them: time_s, acc, gyr with a header.
inline QByteArray imuCsv(const std::vector<footpath::ImuSample>& samples)
{
    QByteArray text = "time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n";
    for (const footpath::ImuSample& s : samples) {
        text += number(s.time_s);
        for (int axis = 0; axis < 3; ++axis)
            text += ',' + number(s.acc_mps2[axis]);
        for (int axis = 0; axis < 3; ++axis)
            text += ',' + number(s.gyr_radps[axis]);
        text += '\n';
    }
    return text;
}

}  // namespace clitest

#define VERIFY_EXIT(run, code)                                                                          \
    do {                                                                                                \
        QVERIFY2((run).finished && (run).status == QProcess::NormalExit && (run).exitCode == (code), \
                 (run).describe().constData());                                                         \
    } while (false)
