#pragma once

#include "Recording.h"
#include "xbus/XbusControl.h"

#include <QMetaType>
#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace footpath {

/// One intact sample from a live device, in the units of ImuSample. Time comes from the device
/// clock (SampleTimeFine, else the packet counter) and starts at 0 with the first sample; lost
/// packets show as longer steps. A magnetic field or pressure the device sends at a lower rate
/// holds its last value (NaN before the first), as the .mtb reader does.
struct LiveSample {
    ImuSample imu;
    std::optional<std::uint16_t> packetCounter;   ///< as the device sent it (wraps at 65536)
    std::optional<std::uint32_t> sampleTimeFine;  ///< as the device sent it (10 kHz ticks)
};

/// Who answered the init sequence.
struct DeviceInfo {
    QString portName;
    std::uint32_t baud = 0;
    std::uint64_t deviceId = 0;
    QString productCode;
    FirmwareRevision firmware;
    std::vector<OutputConfigEntry> requestedOutput;
    std::vector<OutputConfigEntry> appliedOutput;  ///< the device's echo: what it will send
    std::uint16_t rate_hz = 0;                     ///< of the acceleration, as applied

    QString deviceIdText() const { return QString::fromStdString(formatDeviceId(deviceId)); }
};

/// Running totals of one session: what the live panel shows and the CLI prints.
struct DeviceCounters {
    std::uint64_t bytesReceived = 0;
    std::uint64_t framesDecoded = 0;
    std::uint64_t samplesReceived = 0;     ///< intact data messages with acceleration and rate of turn
    std::uint64_t packetsLost = 0;         ///< counter gaps: dropped or damaged on the way
    std::uint64_t checksumErrors = 0;      ///< frames damaged on the way, each once (XbusDecodeStats::damagedFrames)
    std::uint64_t resyncs = 0;             ///< stretches of bytes skipped to find the next frame
    std::uint64_t bytesSkipped = 0;        ///< junk and damaged frames
    std::uint64_t junkBytes = 0;           ///< skipped bytes outside damaged frames: noise between frames
    std::uint64_t malformedMessages = 0;   ///< frames intact but the MTData2 inside was not
    std::uint64_t incompleteMessages = 0;  ///< data messages without acceleration or rate of turn
    std::uint64_t counterRestarts = 0;     ///< the packet counter jumped back (device restart)
    std::uint64_t deviceErrors = 0;        ///< Error messages during measurement
    std::uint64_t samplesNotShown = 0;     ///< dropped from a full display queue (never from the recording)
    double deviceTime_s = 0.0;             ///< time of the last sample
};

/// How long to wait for replies and how often to ask (docs/xbus.md §4.3: XSP waits
/// 500 ms per request and up to 1500 ms for the first GoToConfig after power-up; 3 tries).
struct DeviceTimeouts {
    int reply_ms = 500;
    int goToConfig_ms = 500;  ///< three tries cover the 1500 ms a freshly powered device may need
    int probe_ms = 250;       ///< per other baud rate when the configured one is silent (XSP: 100)
    int tries = 3;
    int stop_ms = 300;        ///< for the GoToConfigAck when a session ends
};

struct RecordingPaths {
    QString mtb;  ///< raw bytes (required to record)
    QString csv;  ///< decoded samples (optional)
    bool isEmpty() const { return mtb.isEmpty(); }
};

/// A snapshot of what a session is asked to do; the worker thread gets its own copy.
struct SessionSettings {
    QString portName;
    std::uint32_t baud = 115200;
    bool probeBaudRates = true;  ///< try the common rates when `baud` gets no answer
    std::uint16_t rate_hz = 100;
    double stopAfter_s = 0.0;    ///< device seconds of samples, then stop; 0: until close()
    RecordingPaths recording;    ///< recorded from the first sample on; empty: not recorded
    DeviceTimeouts timeouts;
    /// Bound of the queue takeSamples() drains (LiveSampleQueue): about 13 MB; 20 minutes at
    /// 100 Hz, 60 s at 2 kHz. A consumer further behind loses the oldest samples from its view
    /// (counted in samplesNotShown); the recording is written before the queue and keeps them.
    std::size_t displayQueueSamples = 120000;
};

/// Where a session is.
enum class SessionState {
    Idle,          ///< no port open
    Initialising,  ///< port open, init sequence running (§4.2)
    Streaming,     ///< measuring: samples arrive
    Stopping,      ///< GoToConfig sent, waiting for the acknowledgement before closing
};

/// Why a session ended.
enum class SessionEnd {
    Stopped,    ///< close() or the requested duration
    Failed,     ///< the port or the device did not work: see the message
    Vanished,   ///< the port went away mid-stream (USB unplugged); everything received was kept
};

}  // namespace footpath

Q_DECLARE_METATYPE(footpath::DeviceInfo)
Q_DECLARE_METATYPE(footpath::DeviceCounters)
Q_DECLARE_METATYPE(footpath::SessionSettings)
Q_DECLARE_METATYPE(footpath::RecordingPaths)
Q_DECLARE_METATYPE(footpath::SessionEnd)
Q_DECLARE_METATYPE(footpath::SessionState)
