// footpath-mti-sim: a live Xsens MTi on a pseudo-terminal, for trying the live panel without
// hardware and for end-to-end tests. The protocol is MtiEmulator's; this file owns the pty, the
// clock and the command line.
#include "MtiEmulator.h"

#include "io/Import.h"
#include "sim/WalkSimulator.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>

#include <algorithm>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <optional>
#include <string>
#include <thread>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

using namespace footpath;

namespace {

constexpr int kExitBadInput = 2;
constexpr int kIdlePoll_ms = 10;            ///< while no host has the port open
constexpr int kMaxPoll_ms = 50;
constexpr double kDrainTimeout_s = 2.0;     ///< for the host to read the last bytes before a disconnect
constexpr int kDrainedChecks = 20;          ///< 5 ms apart: the host's input queue must stay empty this long
constexpr std::size_t kMaxPending = 1 << 20;  ///< output held for a host that stopped reading

volatile std::sig_atomic_t g_stop = 0;

void onSignal(int)
{
    g_stop = 1;
}

struct Options {
    QString recording;
    bool simulate = false;
    QString link;
    QString log;
    double replugAfter_s = 0.0;  ///< after vanishing, come back on the same link after this long; 0: never
    MtiEmulatorConfig emulator;
};

double nowSeconds()
{
    using Clock = std::chrono::steady_clock;
    static const Clock::time_point start = Clock::now();
    return std::chrono::duration<double>(Clock::now() - start).count();
}

void say(const std::string& text)
{
    std::printf("footpath-mti-sim: %s\n", text.c_str());
    std::fflush(stdout);
}

// ---- command line -----------------------------------------------------------------------

void addOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(
        QStringLiteral("Plays a recording as a live Xsens MTi on a pseudo-terminal: answers the init sequence, "
                       "streams MTData2 at the configured rate, and injects faults with a fixed seed."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("recording"), QStringLiteral("any file footpath can import"));
    parser.addOptions({
        {QStringLiteral("simulate"), QStringLiteral("play a simulated walk instead of a recording")},
        {QStringLiteral("link"), QStringLiteral("also reach the port through this symlink"), QStringLiteral("path")},
        {QStringLiteral("speed"), QStringLiteral("device time runs N times faster (default 1)"), QStringLiteral("N")},
        {QStringLiteral("seed"), QStringLiteral("seed of the fault generator (default 1)"), QStringLiteral("N")},
        {QStringLiteral("corrupt-rate"), QStringLiteral("probability of a damaged data message"), QStringLiteral("P")},
        {QStringLiteral("drop-rate"), QStringLiteral("probability of a lost data message"), QStringLiteral("P")},
        {QStringLiteral("junk-rate"), QStringLiteral("probability of junk bytes before a data message"),
         QStringLiteral("P")},
        {QStringLiteral("disconnect-after"), QStringLiteral("vanish after S device seconds of streaming"),
         QStringLiteral("S")},
        {QStringLiteral("burst-at"), QStringLiteral("from S device seconds on, send --burst-factor times faster"),
         QStringLiteral("S")},
        {QStringLiteral("burst-for"), QStringLiteral("length of the burst in device seconds (default 1 if --burst-at)"),
         QStringLiteral("S")},
        {QStringLiteral("burst-factor"), QStringLiteral("how much faster a burst sends (default 10)"),
         QStringLiteral("N")},
        {QStringLiteral("replug-after"),
         QStringLiteral("after vanishing, come back on the same --link after S wall seconds, like a sensor plugged in "
                        "again (try the live panel's reconnect offer)"),
         QStringLiteral("S")},
        {QStringLiteral("once"), QStringLiteral("vanish at the end of the recording instead of playing it again")},
        {QStringLiteral("log"), QStringLiteral("write every data message and its fate to this CSV"),
         QStringLiteral("file")},
    });
}

std::optional<double> numberOption(const QCommandLineParser& parser, const QString& name, double low, double high,
                                   std::string& problem)
{
    if (!parser.isSet(name))
        return std::nullopt;
    bool ok = false;
    const double value = parser.value(name).toDouble(&ok);
    if (!ok || !(value >= low && value <= high))
        problem = "--" + name.toStdString() + " expects a number from " + std::to_string(low) + " to "
                  + std::to_string(high) + ", got '" + parser.value(name).toStdString() + "'";
    return value;
}

std::string readFaults(const QCommandLineParser& parser, MtiEmulatorConfig& config)
{
    std::string problem;
    MtiFaults& faults = config.faults;
    faults.corruptRate = numberOption(parser, QStringLiteral("corrupt-rate"), 0, 1, problem).value_or(0.0);
    faults.dropRate = numberOption(parser, QStringLiteral("drop-rate"), 0, 1, problem).value_or(0.0);
    faults.junkRate = numberOption(parser, QStringLiteral("junk-rate"), 0, 1, problem).value_or(0.0);
    faults.disconnectAfter_s = numberOption(parser, QStringLiteral("disconnect-after"), 0, 1e9, problem).value_or(0.0);
    faults.seed = static_cast<std::uint32_t>(numberOption(parser, QStringLiteral("seed"), 0, 4294967295.0, problem)
                                                 .value_or(1.0));
    const std::optional<double> burstAt = numberOption(parser, QStringLiteral("burst-at"), 0, 1e9, problem);
    faults.burstAt_s = burstAt.value_or(0.0);
    faults.burstLength_s =
        numberOption(parser, QStringLiteral("burst-for"), 0, 1e9, problem).value_or(burstAt ? 1.0 : 0.0);
    faults.burstFactor = numberOption(parser, QStringLiteral("burst-factor"), 1, 1000, problem).value_or(10.0);
    config.speed = numberOption(parser, QStringLiteral("speed"), 1e-3, 1e4, problem).value_or(1.0);
    config.loop = !parser.isSet(QStringLiteral("once"));
    return problem;
}

std::string parseOptions(const QCoreApplication& app, Options& options)
{
    QCommandLineParser parser;
    addOptions(parser);
    parser.process(app);  // --help prints and exits
    const QStringList positional = parser.positionalArguments();
    options.simulate = parser.isSet(QStringLiteral("simulate"));
    if (positional.size() > 1)
        return "one recording at most, got " + std::to_string(positional.size());
    options.recording = positional.value(0);
    if (options.simulate == !options.recording.isEmpty())
        return "give either a recording to play or --simulate";
    options.link = parser.value(QStringLiteral("link"));
    options.log = parser.value(QStringLiteral("log"));
    std::string problem;
    options.replugAfter_s = numberOption(parser, QStringLiteral("replug-after"), 0, 1e6, problem).value_or(0.0);
    if (options.replugAfter_s > 0.0 && options.link.isEmpty())
        problem = "--replug-after needs --link: the pseudo-terminal gets a new name when it comes back";
    return problem.empty() ? readFaults(parser, options.emulator) : problem;
}

// ---- playback ---------------------------------------------------------------------------

std::optional<Recording> loadPlayback(const Options& options, std::string& problem)
{
    if (options.simulate) {
        WalkSimulatorConfig config;
        config.withMagnetometer = true;
        config.withPressure = true;
        config.accNoiseStd_mps2 = 0.02;
        config.gyrNoiseStd_radps = 0.002;
        return simulateWalk(closedRectanglePath(8.0, 4.0), config).recording;
    }
    ImportResult read = importRecording(options.recording.toStdString());
    if (!read.ok()) {
        problem = "cannot play " + options.recording.toStdString() + ": " + read.error->message;
        return std::nullopt;
    }
    if (read.recording.samples.size() < 2) {
        problem = options.recording.toStdString() + " has fewer than two samples";
        return std::nullopt;
    }
    return std::move(read.recording);
}

// ---- the pseudo-terminal ----------------------------------------------------------------

/// The device's end of a pty. The slave side is what hosts open; it is kept closed here so that
/// poll() reports POLLHUP exactly while no host has the port open (Linux), which is the
/// emulator's power switch.
class Pty {
public:
    bool create(std::string& problem)
    {
        termios raw{};
        cfmakeraw(&raw);  // set before any host opens it: no echo, no CR/LF translation
        int slave = -1;
        char name[256] = {};
        if (openpty(&master_, &slave, name, &raw, nullptr) != 0) {
            problem = std::string("cannot create a pseudo-terminal: ") + std::strerror(errno);
            return false;
        }
        ::close(slave);
        fcntl(master_, F_SETFL, fcntl(master_, F_GETFL) | O_NONBLOCK);
        path_ = name;
        return true;
    }
    bool link(const std::string& linkPath, std::string& problem)
    {
        if (QFileInfo(QString::fromStdString(linkPath)).isSymLink())
            ::unlink(linkPath.c_str());  // a stale link from an earlier run
        if (::symlink(path_.c_str(), linkPath.c_str()) != 0) {
            problem = "cannot create the link " + linkPath + ": " + std::strerror(errno);
            return false;
        }
        link_ = linkPath;
        return true;
    }
    ~Pty() { close(); }
    void close()
    {
        if (!link_.empty())
            ::unlink(link_.c_str());
        link_.clear();
        if (master_ >= 0)
            ::close(master_);
        master_ = -1;
    }
    /// Waits until the host has read the slave's input, asked through a second handle opened
    /// just for that. Bytes may still sit in the kernel's flip buffer while the queue reads
    /// empty, so the queue must stay empty for a while.
    void waitUntilDrained(double timeout_s) const
    {
        const int probe = ::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
        if (probe < 0)
            return;
        const double until = nowSeconds() + timeout_s;
        int emptyChecks = 0;
        while (nowSeconds() < until && emptyChecks < kDrainedChecks) {
            int unread = 0;
            if (::ioctl(probe, FIONREAD, &unread) != 0)
                break;
            emptyChecks = unread == 0 ? emptyChecks + 1 : 0;
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        ::close(probe);
    }
    int fd() const { return master_; }
    const std::string& path() const { return path_; }

private:
    int master_ = -1;
    std::string path_;
    std::string link_;
};

// ---- the loop ---------------------------------------------------------------------------

class Runner {
public:
    Runner(Pty& pty, MtiEmulator& emulator) : pty_(pty), emulator_(emulator) {}

    /// Bytes thrown away because the host did not read them in time (not counted as injected faults).
    std::uint64_t unreadBytes() const { return unreadBytes_; }

    void run()
    {
        while (!g_stop && emulator_.state() != MtiEmulator::State::Disconnected)
            step();
        if (emulator_.state() == MtiEmulator::State::Disconnected)
            disconnect();
    }

private:
    void step()
    {
        pollfd p{pty_.fd(), static_cast<short>(POLLIN | (pending_.empty() ? 0 : POLLOUT)), 0};
        ::poll(&p, 1, timeout_ms());
        const bool hostPresent = (p.revents & POLLHUP) == 0;
        if (hostPresent != connected_)
            switchPower(hostPresent);
        if (!connected_) {
            std::this_thread::sleep_for(std::chrono::milliseconds(kIdlePoll_ms));
            return;
        }
        if (p.revents & POLLIN)
            readHost();
        append(emulator_.advance(nowSeconds()));
        writePending();
    }

    int timeout_ms() const
    {
        if (!connected_)
            return 0;
        const double wait_s = emulator_.nextEventAt() - nowSeconds();
        return static_cast<int>(std::clamp(wait_s * 1000.0, 0.0, static_cast<double>(kMaxPoll_ms)));
    }

    void switchPower(bool on)
    {
        connected_ = on;
        pending_.clear();
        if (on) {
            say("a host opened the port: WakeUp");
            append(emulator_.powerOn(nowSeconds()));
        } else {
            say("the host closed the port");
            emulator_.powerOff();
        }
    }

    void readHost()
    {
        std::uint8_t buffer[4096];
        const ssize_t got = ::read(pty_.fd(), buffer, sizeof buffer);
        if (got > 0)
            append(emulator_.receive(buffer, static_cast<std::size_t>(got), nowSeconds()));
    }

    void append(const MtiEmulator::Bytes& bytes)
    {
        pending_.insert(pending_.end(), bytes.begin(), bytes.end());
        if (pending_.size() > kMaxPending) {  // a host that stopped reading: like a device's full TX buffer
            const std::size_t excess = pending_.size() - kMaxPending;
            unreadBytes_ += excess;
            pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(excess));
        }
    }

    void writePending()
    {
        if (pending_.empty())
            return;
        const ssize_t written = ::write(pty_.fd(), pending_.data(), pending_.size());
        if (written > 0)
            pending_.erase(pending_.begin(), pending_.begin() + written);
    }

    /// The port vanishes only after the host has read everything sent, like a cable pulled
    /// between two messages; then the host sees the hang-up.
    void disconnect()
    {
        const double until = nowSeconds() + kDrainTimeout_s;
        while (!pending_.empty() && nowSeconds() < until) {
            writePending();
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        pty_.waitUntilDrained(kDrainTimeout_s);
        say("disconnecting: the port vanishes");
        pty_.close();
    }

    Pty& pty_;
    MtiEmulator& emulator_;
    bool connected_ = false;
    MtiEmulator::Bytes pending_;
    std::uint64_t unreadBytes_ = 0;
};

const char* fateName(MtiEmulator::DataRecord::Fate fate)
{
    switch (fate) {
    case MtiEmulator::DataRecord::Fate::Sent: return "sent";
    case MtiEmulator::DataRecord::Fate::Dropped: return "dropped";
    case MtiEmulator::DataRecord::Fate::Corrupted: return "corrupted";
    }
    return "?";
}

/// The sidecar log: every data message with its counter, SampleTimeFine, fate and values.
void logRecord(std::FILE* log, const MtiEmulator::DataRecord& record)
{
    const MtData2Sample& s = record.sample;
    const Eigen::Vector3d acc = s.acceleration.value_or(Eigen::Vector3d::Zero());
    const Eigen::Vector3d gyr = s.rateOfTurn.value_or(Eigen::Vector3d::Zero());
    std::fprintf(log, "%u,%u,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", unsigned{s.packetCounter.value_or(0)},
                 unsigned{s.sampleTimeFine.value_or(0)}, fateName(record.fate), acc.x(), acc.y(), acc.z(), gyr.x(),
                 gyr.y(), gyr.z());
}

std::FILE* openLog(const QString& path, std::string& problem)
{
    if (path.isEmpty())
        return nullptr;
    std::FILE* log = std::fopen(path.toLocal8Bit().constData(), "w");
    if (log == nullptr) {
        problem = "cannot write the log " + path.toStdString() + ": " + std::strerror(errno);
        return nullptr;
    }
    std::fprintf(log, "packet_counter,sample_time_fine,fate,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n");
    return log;
}

void observeInto(std::FILE* log, MtiEmulator& emulator)
{
    if (log == nullptr)
        return;
    emulator.setDataObserver([log](const MtiEmulator::DataRecord& record) {
        logRecord(log, record);
        std::fflush(log);  // a test may read it while the emulator still runs
    });
}

/// One line of key=value pairs, for people and for the end-to-end tests that compare a host's
/// counters with it.
void sayInjected(const MtiInjected& injected, std::uint64_t unreadBytes)
{
    const auto pair = [](const char* key, std::uint64_t value) {
        return " " + std::string(key) + "=" + std::to_string(value);
    };
    say("injected:" + pair("data_messages", injected.dataMessages) + pair("dropped", injected.dropped)
        + pair("corrupted", injected.corrupted) + pair("corrupted_bytes", injected.corruptedBytes)
        + pair("junk_bytes", injected.junkBytes) + pair("junk_runs", injected.junkRuns)
        + pair("burst_messages", injected.burstMessages) + pair("unread_bytes", unreadBytes));
}

/// Plays until stopped, or until the port vanished and no replug is asked for. Each plug-in is
/// a fresh device: a new pty behind the same link, the playback from its start.
std::string serve(const Options& options, const Recording& playback, std::FILE* log)
{
    for (bool first = true;; first = false) {
        if (!first) {
            say("plugged out; back in " + QString::number(options.replugAfter_s).toStdString() + " s");
            const double until = nowSeconds() + options.replugAfter_s;
            while (!g_stop && nowSeconds() < until)
                std::this_thread::sleep_for(std::chrono::milliseconds(kIdlePoll_ms));
            if (g_stop)
                return {};
        }
        MtiEmulator emulator(playback, options.emulator);
        observeInto(log, emulator);
        Pty pty;
        std::string problem;
        if (!pty.create(problem) || (!options.link.isEmpty() && !pty.link(options.link.toStdString(), problem)))
            return problem;
        say(options.emulator.productCode + " (" + formatDeviceId(options.emulator.deviceId) + ") on " + pty.path()
            + (options.link.isEmpty() ? "" : " = " + options.link.toStdString()) + ", playing "
            + (options.simulate ? std::string("a simulated walk") : options.recording.toStdString()) + " ("
            + std::to_string(playback.samples.size()) + " samples) at speed "
            + QString::number(options.emulator.speed).toStdString());
        Runner runner(pty, emulator);
        runner.run();
        sayInjected(emulator.injected(), runner.unreadBytes());
        if (g_stop || options.replugAfter_s <= 0.0)
            return {};
    }
}

int fail(const std::string& problem)
{
    std::fprintf(stderr, "footpath-mti-sim: %s\n", problem.c_str());
    return kExitBadInput;
}

}  // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    Options options;
    std::string problem = parseOptions(app, options);
    if (!problem.empty())
        return fail(problem);
    std::optional<Recording> playback = loadPlayback(options, problem);
    if (!playback)
        return fail(problem);
    std::FILE* log = openLog(options.log, problem);
    if (!problem.empty())
        return fail(problem);
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    problem = serve(options, *playback, log);
    if (log != nullptr)
        std::fclose(log);
    return problem.empty() ? 0 : fail(problem);
}
