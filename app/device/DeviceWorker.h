#pragma once

#include "DevicePort.h"
#include "DeviceTypes.h"
#include "LiveSampleQueue.h"
#include "Recorder.h"
#include "SampleAssembler.h"
#include "xbus/XbusFrame.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QTimer>

#include <memory>
#include <vector>

namespace footpath {

/// The serial side of a DeviceSession, living in the session's worker thread: opens the port,
/// runs the init sequence of docs/xbus.md §4 (wake-up handling, timeouts, retries, a
/// baud probe), streams, records, and ends cleanly when asked or when the port vanishes. Event
/// driven: it never blocks its thread, so bytes keep flowing while it waits for a reply.
class DeviceWorker : public QObject {
    Q_OBJECT
public:
    DeviceWorker(DevicePortFactory factory, LiveSampleQueue& queue, QObject* parent = nullptr);
    ~DeviceWorker() override;

    void start(const SessionSettings& settings);
    /// Ends a session politely: GoToConfig so the device stops streaming, then close.
    void stop();
    void startRecording(const RecordingPaths& paths);
    void stopRecording();
    /// Ends at once (the session object is going away): files closed, port closed, no waiting.
    void shutdown();

signals:
    void stateChanged(footpath::SessionState state);
    void progress(const QString& step);
    void deviceIdentified(const footpath::DeviceInfo& info);
    void samplesQueued();
    void countersChanged(const footpath::DeviceCounters& counters);
    void warning(const QString& text);
    void recordingStarted(const footpath::RecordingPaths& paths);
    void recordingStopped(const footpath::RecordingPaths& paths, const QString& error);
    void ended(footpath::SessionEnd how, const QString& message);

private:
    /// One step of the init sequence.
    struct Request {
        XbusMessage message;
        std::uint8_t replyMid = 0;
    };

    void wirePort();
    void releasePort();
    void resetStream();
    bool openPort();
    void beginInit();
    void sendRequest();
    void resendNow();
    void onReplyTimeout();
    bool tryNextBaud();
    void onReadyRead();
    void onPortFailed(DevicePort::Failure kind, const QString& message);
    void dispatch(const XbusMessage& message);
    void handleInitMessage(const XbusMessage& message);
    void completeStep(const XbusMessage& reply);
    QString applyReply(const XbusMessage& reply);
    QString applyOutputConfiguration(const XbusMessage& reply);
    void warnAboutOutputDifferences();
    void enterStreaming();
    void handleStreamMessage(const XbusMessage& message);
    void handleDataMessage(const XbusMessage& message);
    void warnAtMostOncePerSecond(const QString& text);
    void deliverBatch();
    std::uint64_t recordableEnd() const;
    void flushRaw(std::uint64_t upToOffset);
    void cutAndStop(std::uint64_t cutOffset);
    void finishStop();
    void endSession(SessionEnd how, const QString& message);
    void failInit(const QString& message);
    void recordingFailed(const QString& error);
    void closeRecording();
    void updateCounters();
    void emitCounters();
    void setState(SessionState state);

    int currentTimeout() const;
    int currentTries() const;
    std::uint32_t currentBaud() const { return bauds_.at(baudIndex_); }
    QString requestName() const;
    QString noAnswerMessage() const;
    QString summary() const;

    DevicePortFactory factory_;
    LiveSampleQueue& queue_;
    std::unique_ptr<DevicePort> port_;
    SessionSettings settings_;
    SessionState state_ = SessionState::Idle;
    DeviceInfo info_;
    DeviceCounters counters_;
    bool countersDirty_ = false;

    // Init sequence
    std::vector<Request> requests_;
    std::size_t requestIndex_ = 0;
    int tries_ = 0;
    std::vector<std::uint32_t> bauds_;
    std::size_t baudIndex_ = 0;
    bool bytesWithoutFrames_ = false;  ///< something arrived during the probe, never a valid frame
    QTimer replyTimer_{this};  // children, so that they move to the worker thread with it

    // Stream
    XbusFrameDecoder decoder_;
    SampleAssembler assembler_;
    QByteArray rawPending_;             ///< received bytes not yet handed to the recorder
    std::uint64_t rawPendingOffset_ = 0;  ///< stream offset of rawPending_'s first byte
    std::uint64_t lastMessageEnd_ = 0;    ///< stream offset just past the last whole message
    std::vector<LiveSample> batch_;
    std::vector<MtData2Sample> recordBatch_;
    Recorder recorder_;
    bool recordingHeaderDue_ = false;
    QTimer countersTimer_{this};
    QTimer syncTimer_{this};
    QElapsedTimer warningClock_;
    QHash<QString, qint64> lastWarningAt_ms_;  ///< per distinct streaming warning
};

}  // namespace footpath
