#pragma once

#include "DeviceSession.h"
#include "Recording.h"
#include "Result.h"

#include <QFutureWatcher>
#include <QWidget>

#include <memory>
#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QSplitter;
class QTimer;

namespace footpath {

class SignalPlots;
class TrajectoryView2D;

/// The "Live input" dock: connects to an Xsens MTi (or the emulator's pseudo-terminal), shows
/// the device, the counters, the last seconds of signals and the path estimated so far, and
/// records to .mtb plus CSV. When a recording ends, recordingFinished() hands its path on so
/// the workspace can open it as a recorded walk.
class LivePanel : public QWidget {
    Q_OBJECT
public:
    explicit LivePanel(QWidget* parent = nullptr);
    ~LivePanel() override;

    /// Starts a session on `port` with the baud and rate chosen in the panel.
    void connectTo(const QString& port);
    void disconnectDevice();
    /// Records to `mtbPath` and a CSV beside it with the same base name. Before a session is
    /// streaming, the recording starts with the first sample of the next connection.
    void startRecordingTo(const QString& mtbPath);
    void stopRecording();

    DeviceSession* session() const { return session_; }
    /// The latest live estimate (null until the first run finished).
    std::shared_ptr<const Result> lastResult() const { return lastResult_; }
    /// Samples received in this session so far.
    std::size_t sampleCount() const { return samples_.size(); }
    /// How far the estimate lags behind the device, from the detector's look-ahead window.
    static double latency_s();

signals:
    /// A recording was closed (stopped, or the session ended); `mtbPath` can be opened.
    void recordingFinished(const QString& mtbPath);
    /// The trajectory view shows a new live estimate.
    void trajectoryUpdated();

private:
    void buildUi();
    void ensureViews();
    void wireSession();
    void refreshPorts();
    void onConnectClicked();
    void onRecordClicked();
    void onStateChanged(SessionState state);
    void onSamplesAvailable();
    void onCounters(const DeviceCounters& counters);
    void onRecordingStopped(const RecordingPaths& paths, const QString& error);
    void onEnded(SessionEnd how, const QString& message);
    void finishRecording(const QString& mtbPath);
    void redrawSignals();
    void startEstimate();
    void onEstimateDone();
    void updateButtons();

    DeviceSession* session_;
    QComboBox* port_ = nullptr;
    QComboBox* baud_ = nullptr;
    QSpinBox* rate_ = nullptr;
    QPushButton* connect_ = nullptr;
    QPushButton* record_ = nullptr;
    QLabel* status_ = nullptr;
    QLabel* deviceId_ = nullptr;
    QLabel* productCode_ = nullptr;
    QLabel* firmware_ = nullptr;
    QLabel* deviceBaud_ = nullptr;
    QLabel* samplesLabel_ = nullptr;
    QLabel* lostLabel_ = nullptr;
    QLabel* checksumLabel_ = nullptr;
    QLabel* resyncLabel_ = nullptr;
    QLabel* latency_ = nullptr;
    QSplitter* views_ = nullptr;
    SignalPlots* plots_ = nullptr;  ///< made on the first connection
    TrajectoryView2D* trajectory_ = nullptr;  ///< made on the first connection
    QTimer* plotTimer_ = nullptr;
    QTimer* estimateTimer_ = nullptr;

    std::vector<ImuSample> samples_;
    bool plotDirty_ = false;
    std::size_t estimatedSamples_ = 0;  ///< samples the last started estimate used
    QFutureWatcher<std::shared_ptr<const Result>> estimate_;
    std::shared_ptr<const Result> lastResult_;
    QString recordingPath_;  ///< the .mtb being recorded (or pending for the next session)
    bool recordingActive_ = false;
};

}  // namespace footpath
