#pragma once

#include "DevicePort.h"
#include "DeviceTypes.h"
#include "LiveSampleQueue.h"

#include <QObject>
#include <QThread>

#include <vector>

namespace footpath {

class DeviceWorker;

/// A live Xsens MTi session, for the GUI and the CLI alike. The port, the protocol and the
/// recorder run in a DeviceWorker on a thread of their own; this facade lives in the caller's
/// thread, forwards requests to the worker and re-emits its signals there.
///
/// Typical use: connect the signals, start(settings); on samplesAvailable() call takeSamples();
/// on ended() the session is over (SessionEnd and a message in words). The recording, if any,
/// is written in the worker thread and never waits for the consumer of takeSamples().
class DeviceSession : public QObject {
    Q_OBJECT
public:
    /// `factory` makes the port in the worker thread: serialDevicePortFactory() for hardware
    /// and pseudo-terminals, MockSerialLine::factory() in tests.
    explicit DeviceSession(DevicePortFactory factory = serialDevicePortFactory(), QObject* parent = nullptr);
    /// Ends a running session at once (recording closed, port closed) and stops the thread.
    ~DeviceSession() override;

    void start(const SessionSettings& settings);
    /// Stops streaming (GoToConfig) and closes; ended() follows.
    void stop();
    /// Records from the next received bytes on; recordingStarted() or recordingStopped(error) follows.
    void startRecording(const RecordingPaths& paths);
    void stopRecording();

    /// Every sample queued since the last call, in arrival order.
    std::vector<LiveSample> takeSamples();
    SessionState state() const { return state_; }
    const DeviceInfo& deviceInfo() const { return info_; }
    const DeviceCounters& counters() const { return counters_; }

signals:
    void stateChanged(footpath::SessionState state);
    /// What the init sequence is doing, for a status line.
    void progress(const QString& step);
    void deviceIdentified(const footpath::DeviceInfo& info);
    /// New samples wait in takeSamples(); sent once until they are taken.
    void samplesAvailable();
    void countersChanged(const footpath::DeviceCounters& counters);
    /// Something the user should know that does not end the session.
    void warning(const QString& text);
    void recordingStarted(const footpath::RecordingPaths& paths);
    /// `error` is empty when the recording was stopped as asked; else it says why it stopped.
    void recordingStopped(const footpath::RecordingPaths& paths, const QString& error);
    void ended(footpath::SessionEnd how, const QString& message);

private:
    void wireWorker();

    LiveSampleQueue queue_{SessionSettings{}.displayQueueSamples};
    QThread thread_;
    DeviceWorker* worker_ = nullptr;  ///< lives in thread_, deleted when it finishes
    SessionState state_ = SessionState::Idle;
    DeviceInfo info_;
    DeviceCounters counters_;
};

}  // namespace footpath
