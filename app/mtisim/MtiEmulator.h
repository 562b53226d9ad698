#pragma once

#include "Recording.h"
#include "xbus/MtData2.h"
#include "xbus/XbusControl.h"
#include "xbus/XbusFrame.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace footpath {

/// Faults the emulator injects into its data stream, drawn from a generator with a fixed seed so
/// that a run can be repeated byte for byte.
struct MtiFaults {
    double corruptRate = 0.0;  ///< probability that a data message has one byte altered (checksum fails)
    double dropRate = 0.0;     ///< probability that a data message is not sent at all
    double junkRate = 0.0;     ///< probability of 1..16 junk bytes before a data message
    double disconnectAfter_s = 0.0;  ///< device seconds of streaming after which the port vanishes; 0: never
    std::uint32_t seed = 1;
    /// From device time burstAt_s on, for burstLength_s of device time, messages leave burstFactor
    /// times faster than the rate (a device emptying its buffer); their time stamps keep the rate.
    double burstAt_s = 0.0;
    double burstLength_s = 0.0;  ///< 0: no burst
    double burstFactor = 10.0;
};

/// What the emulator injected into its data stream so far: the truth a host's counters are
/// compared with.
struct MtiInjected {
    std::uint64_t dataMessages = 0;    ///< data messages made, dropped ones included
    std::uint64_t dropped = 0;
    std::uint64_t corrupted = 0;
    std::uint64_t corruptedBytes = 0;  ///< bytes of the corrupted frames
    std::uint64_t junkBytes = 0;
    std::uint64_t junkRuns = 0;
    std::uint64_t burstMessages = 0;   ///< data messages sent at the burst rate
};

/// Who the emulated device says it is, and how it behaves (docs/xbus.md §4.6).
struct MtiEmulatorConfig {
    std::uint64_t deviceId = 0x037003F8;  ///< an MTi-300 (the protocol sheet's example)
    std::string productCode = "MTi-300-2A8G4";
    FirmwareRevision firmware{1, 8, 2, 37, 70964};
    double wakeUpWindow_s = 0.5;  ///< wall time the host has to answer WakeUp (§4.1)
    double bootTime_s = 0.05;     ///< wall time between a Reset and the next WakeUp
    double speed = 1.0;           ///< device time runs this many times faster than wall time
    bool loop = true;             ///< play the recording again from the start when it ends
    std::uint16_t firstPacketCounter = 0;
    std::uint32_t firstSampleTimeFine = 0;
    MtiFaults faults;
};

/// A live MTi in bytes: host bytes go in through receive(), the device's bytes come out of
/// powerOn(), receive() and advance(). Time is passed in (wall seconds from any origin), so the
/// class does no I/O and no sleeping and tests drive it directly; the pty and the clock live in
/// footpath-mti-sim's main.
///
/// It answers the init sequence as a device does (WakeUp, acks, DeviceID, ProductCode, firmware,
/// output configuration echo, Error 4 for what it does not know), plays `playback` as MTData2 at
/// the configured rate, and injects MtiFaults.
class MtiEmulator {
public:
    using Bytes = std::vector<std::uint8_t>;
    enum class State { Off, Booting, WakingUp, Config, Measurement, Disconnected };

    /// What became of one data message, for a sidecar log the end-to-end tests compare with.
    struct DataRecord {
        enum class Fate { Sent, Dropped, Corrupted };
        Fate fate = Fate::Sent;
        MtData2Sample sample;  ///< the values as encoded (float32 unless the host asked otherwise)
    };
    using DataObserver = std::function<void(const DataRecord&)>;

    /// Rate limits of the emulated device (MTi 10/100-series, MAN-10): the inertial sensors run
    /// at divisors of 2000 Hz, the magnetometer up to 100 Hz, the barometer up to 50 Hz.
    static constexpr std::uint16_t kInertialMax_hz = 2000;
    static constexpr std::uint16_t kMagneticMax_hz = 100;
    static constexpr std::uint16_t kPressureMax_hz = 50;

    /// `playback` needs at least two samples; its magnetic field and pressure decide whether the
    /// device has a magnetometer and a barometer.
    MtiEmulator(Recording playback, MtiEmulatorConfig config);

    void setDataObserver(DataObserver observer) { observer_ = std::move(observer); }

    /// The device is switched on (the host opened the port): WakeUp, then the 500 ms window.
    Bytes powerOn(double now_s);
    /// The device loses power (the host closed the port): silent until the next powerOn().
    void powerOff();
    Bytes receive(const std::uint8_t* data, std::size_t size, double now_s);
    Bytes receive(const Bytes& data, double now_s) { return receive(data.data(), data.size(), now_s); }
    /// Everything due by `now_s`: the end of the WakeUp window, the WakeUp after a reset, data.
    Bytes advance(double now_s);
    /// When advance() next has something to do; infinity when nothing is scheduled.
    double nextEventAt() const;

    State state() const { return state_; }
    const std::vector<OutputConfigEntry>& outputConfiguration() const { return outputConfiguration_; }
    std::uint8_t baudCode() const { return baudCode_; }
    std::uint64_t dataMessagesSent() const { return injected_.dataMessages; }  ///< including dropped ones
    const MtiInjected& injected() const { return injected_; }
    double streamedDeviceTime_s() const { return deviceTime_s_; }

    /// The Configuration message (0x0D) this device sends before streaming after power-up.
    XbusConfiguration configuration() const;

private:
    void handleMessage(const XbusMessage& message, double now_s, Bytes& out);
    void handleInConfig(const XbusMessage& message, double now_s, Bytes& out);
    void handleInMeasurement(const XbusMessage& message, double now_s, Bytes& out);
    void handleOutputConfiguration(const XbusMessage& message, Bytes& out);
    void startMeasurement(double now_s, Bytes& out);
    void startReset(double now_s, Bytes& out);
    void sendWakeUp(double now_s, Bytes& out);
    std::uint8_t validateOutputConfiguration(std::vector<OutputConfigEntry>& entries) const;
    bool applyEntry(OutputConfigEntry& entry, std::uint8_t& error) const;
    void streamDue(double now_s, Bytes& out);
    void emitDataMessage(Bytes& out);
    MtData2Sample sampleForMessage() const;
    Bytes encodeDataPayload(const MtData2Sample& sample) const;
    bool itemDue(std::uint16_t rate_hz) const;
    const ImuSample* playbackSample() const;
    void emitWithFaults(Bytes frame, DataRecord& record, Bytes& out);
    std::uint16_t messageRate() const;
    bool inBurst() const;
    double sendRate() const;  ///< messages per wall second for the next message
    void rescheduleIfRateChanged();

    Recording playback_;
    MtiEmulatorConfig config_;
    bool hasMag_ = false;
    bool hasPressure_ = false;
    double playbackPeriod_s_ = 0.01;
    DataObserver observer_;
    XbusFrameDecoder decoder_;
    std::mt19937 random_;

    State state_ = State::Off;
    double deadline_s_ = std::numeric_limits<double>::infinity();  ///< WakeUp window end or boot end
    std::vector<OutputConfigEntry> outputConfiguration_;
    std::uint8_t baudCode_ = 0x02;  ///< 115200

    std::uint64_t streamMessages_ = 0;  ///< data messages since the current GoToMeasurement
    double segmentStart_s_ = 0.0;       ///< wall time since which messages leave at segmentRate_
    std::uint64_t segmentMessages_ = 0; ///< data messages since segmentStart_s_
    double segmentRate_ = 0.0;          ///< messages per wall second (a burst changes it)
    std::uint16_t packetCounter_ = 0;   ///< of the next data message
    std::uint32_t sampleTimeFine_ = 0;  ///< of the next data message
    double deviceTime_s_ = 0.0;         ///< streamed device time: the playback position
    MtiInjected injected_;
};

}  // namespace footpath
