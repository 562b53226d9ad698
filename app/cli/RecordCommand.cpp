#include "cli/RecordCommand.h"

#include "DeviceSession.h"
#include "cli/CliSupport.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTimer>

#include <csignal>
#include <cstdio>

namespace footpath::cli {

namespace {

constexpr int kCountersEvery_ms = 1000;
constexpr int kSignalPoll_ms = 100;
constexpr int kExitDeviceProblem = 2;

volatile std::sig_atomic_t g_interrupted = 0;

void onInterrupt(int)
{
    g_interrupted = 1;
}

SessionSettings settingsFrom(const CommandLine& cmd)
{
    SessionSettings settings;
    settings.portName = QString::fromStdString(cmd.port);
    if (cmd.baud > 0.0) {
        settings.baud = static_cast<std::uint32_t>(cmd.baud);
        settings.probeBaudRates = false;  // the user said which rate
    }
    if (cmd.rate_hz > 0.0)
        settings.rate_hz = static_cast<std::uint16_t>(cmd.rate_hz);
    settings.stopAfter_s = cmd.duration_s;
    settings.recording.mtb = QString::fromStdString(cmd.outFile);
    settings.recording.csv = QString::fromStdString(cmd.csvOut);
    // Nothing here looks at the samples: hold none for a view (the recorder never depends on it).
    settings.displayQueueSamples = 1;
    return settings;
}

void printDevice(const DeviceInfo& info)
{
    std::printf("device      %s %s, firmware %s\nport        %s at %u baud\noutput      %s\n",
                info.deviceIdText().toStdString().c_str(), info.productCode.toStdString().c_str(),
                info.firmware.toString().c_str(), info.portName.toStdString().c_str(), info.baud,
                describeOutputConfiguration(info.appliedOutput).c_str());
    std::fflush(stdout);
}

void printCounters(const DeviceCounters& c)
{
    std::printf("t = %7.2f s  samples %llu  lost %llu  checksum errors %llu  junk bytes %llu  resyncs %llu\n",
                c.deviceTime_s, static_cast<unsigned long long>(c.samplesReceived),
                static_cast<unsigned long long>(c.packetsLost), static_cast<unsigned long long>(c.checksumErrors),
                static_cast<unsigned long long>(c.junkBytes), static_cast<unsigned long long>(c.resyncs));
    std::fflush(stdout);
}

void printFiles(const RecordingPaths& paths)
{
    for (const QString& path : {paths.mtb, paths.csv})
        if (!path.isEmpty())
            std::printf("recorded    %s (%lld bytes)\n", path.toStdString().c_str(), QFileInfo(path).size());
}

/// Runs one session on the event loop and remembers how it ended.
class RecordRun {
public:
    RecordRun(DeviceSession& session, const SessionSettings& settings) : session_(session), settings_(settings) {}

    int exec(QCoreApplication& app)
    {
        wire(app);
        QTimer interruptPoll;
        QObject::connect(&interruptPoll, &QTimer::timeout, &session_, [this] {
            if (g_interrupted && !stopping_) {
                stopping_ = true;  // Ctrl+C: stop politely so the files end on a whole message
                session_.stop();
            }
        });
        interruptPoll.start(kSignalPoll_ms);
        session_.start(settings_);
        app.exec();
        return finish();
    }

private:
    void wire(QCoreApplication& app)
    {
        QObject::connect(&session_, &DeviceSession::deviceIdentified, &app, &printDevice);
        QObject::connect(&session_, &DeviceSession::warning, &app, [](const QString& text) {
            std::fprintf(stderr, "warning: %s\n", text.toStdString().c_str());
        });
        QObject::connect(&session_, &DeviceSession::countersChanged, &app, [this](const DeviceCounters& counters) {
            if (!sinceLastPrint_.isValid() || sinceLastPrint_.elapsed() >= kCountersEvery_ms) {
                sinceLastPrint_.start();
                printCounters(counters);
            }
        });
        QObject::connect(&session_, &DeviceSession::recordingStopped, &app,
                         [this](const RecordingPaths&, const QString& error) {
                             if (error.isEmpty())
                                 return;
                             // At once, not after the device has acknowledged the stop.
                             std::fprintf(stderr, "footpath-cli: %s\n", error.toStdString().c_str());
                             std::fflush(stderr);
                             recordingError_ = error;
                             session_.stop();  // a recording that cannot be written is not worth streaming
                         });
        QObject::connect(&session_, &DeviceSession::ended, &app, [this, &app](SessionEnd how, const QString& message) {
            end_ = how;
            endMessage_ = message;
            app.quit();
        });
    }

    int finish()
    {
        if (end_ == SessionEnd::Failed)
            throw BadInput{endMessage_.toStdString()};
        printCounters(session_.counters());
        printFiles(settings_.recording);
        if (!recordingError_.isEmpty())
            return kExitDeviceProblem;  // said when it happened; the files hold what was written
        if (end_ == SessionEnd::Vanished) {  // the recording is kept, but it is shorter than asked
            std::fprintf(stderr, "footpath-cli: %s\n", endMessage_.toStdString().c_str());
            return kExitDeviceProblem;
        }
        std::printf("%s\n", endMessage_.toStdString().c_str());
        return 0;
    }

    DeviceSession& session_;
    SessionSettings settings_;
    QElapsedTimer sinceLastPrint_;
    bool stopping_ = false;
    SessionEnd end_ = SessionEnd::Failed;
    QString endMessage_;
    QString recordingError_;
};

}  // namespace

int runRecord(const CommandLine& cmd)
{
    int argc = 1;
    char name[] = "footpath-cli";
    char* argv[] = {name, nullptr};
    QCoreApplication app(argc, argv);
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
    // Past a file size limit (ulimit -f) a write then fails with EFBIG, which the recorder reports
    // and survives, instead of the signal killing the process mid-write.
    std::signal(SIGXFSZ, SIG_IGN);
    DeviceSession session;
    return RecordRun(session, settingsFrom(cmd)).exec(app);
}

}  // namespace footpath::cli
