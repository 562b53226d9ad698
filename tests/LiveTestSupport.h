#pragma once

// What the live end-to-end tests share: footpath-mti-sim on a pseudo-terminal, and its sidecar
// log of every data message it sent, which is the truth the received samples are checked against.

#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QtTest>

#include <array>
#include <vector>

#ifndef FOOTPATH_MTI_SIM
#error "FOOTPATH_MTI_SIM must name the footpath-mti-sim binary"
#endif

namespace livetest {

/// One data message as the emulator's sidecar log lists it.
struct Sent {
    unsigned counter = 0;
    unsigned sampleTimeFine = 0;
    QString fate;  ///< sent, dropped, corrupted
    std::array<double, 6> values{};  ///< acc x y z, gyr x y z as the device encoded them
    bool intact() const { return fate == QLatin1String("sent"); }
};

/// The lines after the header of a CSV file, without empty ones.
inline QList<QByteArray> dataLines(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QList<QByteArray> lines = file.readAll().split('\n');
    lines.removeFirst();  // header
    lines.removeAll(QByteArray());
    return lines;
}

inline std::vector<Sent> readSentLog(const QString& path)
{
    std::vector<Sent> sent;
    for (const QByteArray& line : dataLines(path)) {
        const QList<QByteArray> cells = line.split(',');
        Sent s;
        s.counter = cells.at(0).toUInt();
        s.sampleTimeFine = cells.at(1).toUInt();
        s.fate = QString::fromLatin1(cells.at(2));
        for (int i = 0; i < 6; ++i)
            s.values[std::size_t(i)] = cells.at(3 + i).toDouble();
        sent.push_back(s);
    }
    return sent;
}

/// The sent messages the host should have: sent intact, from the first received one on, within
/// `window_s` of device time (all if 0).
inline std::vector<Sent> expectedSamples(const std::vector<Sent>& sent, unsigned firstTime, double window_s)
{
    std::vector<Sent> expected;
    for (const Sent& s : sent) {
        const double age_s = (double(s.sampleTimeFine) - double(firstTime)) / 10000.0;
        if (s.intact() && age_s >= 0.0 && (window_s <= 0.0 || age_s < window_s - 1e-9))
            expected.push_back(s);
    }
    return expected;
}

/// footpath-mti-sim playing a simulated walk on a pty reachable through `link`; stopped on
/// destruction.
class Emulator {
public:
    ~Emulator() { stop(); }

    /// Empty on success, else why the emulator did not come up. `log` may be empty.
    QString start(const QString& link, const QString& log, const QStringList& extra)
    {
        QStringList args{QStringLiteral("--simulate"), QStringLiteral("--link"), link};
        if (!log.isEmpty())
            args << QStringLiteral("--log") << log;
        process_.start(QString::fromUtf8(FOOTPATH_MTI_SIM), args + extra);
        if (!process_.waitForStarted(5000))
            return QStringLiteral("footpath-mti-sim did not start: ") + process_.errorString();
        for (int waited = 0; waited < 10000 && !QFileInfo(link).isSymLink(); waited += 10) {
            if (process_.waitForFinished(10))
                return QString::fromLocal8Bit(process_.readAllStandardError());
        }
        return QFileInfo(link).isSymLink() ? QString() : QStringLiteral("the emulator's port did not appear");
    }
    bool waitForExit() { return process_.waitForFinished(10000); }
    /// What it printed; complete once it has exited (waitForExit() or stop()).
    QString output() { return QString::fromLocal8Bit(process_.readAllStandardOutput()); }
    void stop()
    {
        if (process_.state() == QProcess::NotRunning)
            return;
        process_.terminate();
        if (!process_.waitForFinished(5000))
            process_.kill();
        process_.waitForFinished(1000);
    }

private:
    QProcess process_;
};

}  // namespace livetest
