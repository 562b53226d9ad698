#pragma once

#include "DeviceSession.h"
#include "Result.h"
#include "nav/Parameters.h"

#include <QPointer>
#include <QWidget>

#include <array>
#include <memory>
#include <vector>

class QComboBox;
class QDateTime;
class QFormLayout;
class QLabel;
class QPushButton;
class QSpinBox;
class QSplitter;
class QTabWidget;
class QTimer;
class QVBoxLayout;

namespace footpath {

class LiveReestimator;
class LiveViews;
class SummaryPanel;
class ReconnectOffer;
class StreamingEstimator;

/// The "Live input" dock: connects to an Xsens MTi (or the emulator's pseudo-terminal), shows
/// the device and the counters, runs the estimator causally on the samples as they arrive and
/// shows the path, the last seconds of signals and the detector's lanes (LiveViews), and
/// records to .mtb plus CSV. When a recording ends, recordingFinished() hands its path on so
/// the workspace can open it as a recorded walk. When the port vanishes mid-stream it offers
/// to reconnect, continuing an interrupted recording in a new file.
class LivePanel : public QWidget {
    Q_OBJECT
public:
    explicit LivePanel(QWidget* parent = nullptr);
    ~LivePanel() override;

    /// Starts a session on `port` with the baud and rate chosen in the panel. A new session
    /// starts with no samples: unsaved ones of the last session are offered for saving first
    /// (mayEndSession); returns false when the user kept them (Cancel) or a session is running.
    /// What ends the samples in memory, for the question asked before it happens.
    enum class SessionEnding { Connect, Reconnect, Quit };
    bool connectTo(const QString& port, SessionEnding ending = SessionEnding::Connect);
    /// Whether the samples in memory may go: true when they are recorded or saved already, or the
    /// user saved them now or chose to discard them; false when the user cancelled. Every path
    /// that ends them asks here (Connect, Reconnect, quitting the window).
    bool mayEndSession(SessionEnding ending);
    void disconnectDevice();
    /// Records to `mtbPath` and a CSV beside it with the same base name. Before a session is
    /// streaming, the recording starts with the first sample of the next connection.
    void startRecordingTo(const QString& mtbPath);
    void stopRecording();
    /// The estimator's parameters (the workspace's); re-estimates what was received so far off
    /// the GUI thread (the views keep the old estimate until the new one has caught up).
    void setParameters(const Parameters& params);
    /// Whether a re-estimate after a parameter change is running.
    bool isReestimating() const;
    /// How many samples wait for the views at the most from the next connection on
    /// (SessionSettings::displayQueueSamples); beyond it the oldest are not shown, only counted
    /// ("Not shown"). Tests make it small to fall behind in seconds instead of minutes.
    void setDisplayQueueSamples(std::size_t samples) { displayQueueSamples_ = samples; }
    /// Moves the live views out of the panel into the workspace's tab widgets.
    void moveViewsInto(QTabWidget* trajectoryTabs, QTabWidget* signalTabs);
    /// While a live view is the current tab of the workspace (after moveViewsInto), `summary`
    /// shows this session's figures as they grow; when the user goes back to the recorded walk's
    /// views, the recorded walk's.
    void linkSummary(SummaryPanel* summary);

    DeviceSession* session() const { return session_; }
    LiveViews* views() const { return views_; }
    ReconnectOffer* reconnectOffer() const { return reconnect_; }
    /// Every intact sample of this session, in arrival order.
    const std::vector<LiveSample>& receivedSamples() const { return received_; }
    std::size_t sampleCount() const { return received_.size(); }
    /// The causal estimate so far (null before the first connection).
    const StreamingEstimator* estimator() const { return estimator_.get(); }
    /// What the trajectory views show now, with the plausibility warnings so far (null until the
    /// first path was drawn). The same object grows at each refresh (trajectoryUpdated) until the
    /// estimate restarts (new parameters or session).
    std::shared_ptr<const Result> lastResult() const { return lastResult_; }
    /// How far the estimate trails the newest sample: the detector's look-ahead.
    double latency_s() const;
    /// Where Record... proposes to write: the folder of the last recording (else the documents
    /// folder), named after the device and the time (MTi-<device id>-2026-11-25-1432.mtb).
    QString suggestedRecordingPath() const;
    /// Writes the samples of this (or the last) session to `csvPath`, for a session that was not
    /// recorded; the workspace is asked to open it. Returns an error, or empty.
    QString saveSamplesTo(const QString& csvPath);
    /// Samples received that are neither recorded nor saved (lost by the next Connect).
    bool hasUnsavedSamples() const;
    /// The error of the last session that failed (a bad port), shown in a banner; empty if none.
    QString errorText() const;
    /// The state line ("Not connected", "Streaming", ...).
    QString statusText() const;
    /// The session's line for the window's status bar: its figures so far, or its state before
    /// the first sample.
    QString statusLine() const;

signals:
    /// A recording was closed (stopped, or the session ended); `mtbPath` can be opened.
    void recordingFinished(const QString& mtbPath);
    /// The trajectory views show a new live estimate.
    void trajectoryUpdated();
    /// A session starts: the workspace may bring the live views to the front.
    void sessionStarted();
    /// While a live view is the current tab of the workspace: statusLine(), again whenever it
    /// changes; an empty line when the user goes back to the recorded walk's views.
    void liveStatusChanged(const QString& line);

private:
    void buildUi();
    QWidget* buildEstimateBox();
    void wireSession();
    void refreshPorts();
    void onConnectClicked();
    void onRecordClicked();
    void onSaveClicked();
    bool confirmDiscardingSamples(SessionEnding ending);
    void showError(const QString& message);
    void updateNotice();
    void onReconnect();
    void onStateChanged(SessionState state);
    void onSamplesAvailable();
    void onCounters(const DeviceCounters& counters);
    void onRecordingStopped(const RecordingPaths& paths, const QString& error);
    void onEnded(SessionEnd how, const QString& message);
    void finishRecording(const QString& mtbPath);
    void restartEstimate();
    /// The re-estimate for the current parameters arrived: it takes over from the old estimator.
    void adoptReestimate(std::shared_ptr<StreamingEstimator> estimator, std::size_t samples);
    void refreshViews(bool force = false);
    void showEstimateFigures();
    void showLiveSummary();
    std::vector<PlausibilityWarning> currentWarnings() const;
    bool liveViewShown() const;
    void showSummarySource();
    void publishStatusLine();
    void updateButtons();

    DeviceSession* session_;
    QComboBox* port_ = nullptr;
    QComboBox* baud_ = nullptr;
    QSpinBox* rate_ = nullptr;
    QPushButton* connect_ = nullptr;
    QPushButton* record_ = nullptr;
    QPushButton* save_ = nullptr;
    QLabel* error_ = nullptr;
    QLabel* status_ = nullptr;
    ReconnectOffer* reconnect_ = nullptr;
    QLabel* deviceId_ = nullptr;
    QLabel* productCode_ = nullptr;
    QLabel* firmware_ = nullptr;
    QLabel* deviceBaud_ = nullptr;
    QLabel* samplesLabel_ = nullptr;
    QLabel* lostLabel_ = nullptr;
    QLabel* checksumLabel_ = nullptr;
    QLabel* resyncLabel_ = nullptr;
    QLabel* notShownLabel_ = nullptr;  ///< its row shows only once the display queue overflowed
    QFormLayout* countersForm_ = nullptr;
    QLabel* latency_ = nullptr;
    QLabel* estimateState_ = nullptr;
    QLabel* steps_ = nullptr;
    QLabel* distance_ = nullptr;
    QLabel* duration_ = nullptr;
    QLabel* endToStart_ = nullptr;
    QLabel* warnings_ = nullptr;
    QVBoxLayout* contentLayout_ = nullptr;
    QSplitter* viewArea_ = nullptr;
    LiveViews* views_ = nullptr;
    /// Where moveViewsInto put the views; guarded, as the session's last state change may come
    /// after the workspace's tab widgets are gone.
    std::array<QPointer<QTabWidget>, 2> workspaceTabs_{};
    SummaryPanel* summary_ = nullptr;             ///< the workspace's, from linkSummary
    QTimer* viewTimer_ = nullptr;

    Parameters params_;
    std::size_t displayQueueSamples_ = SessionSettings{}.displayQueueSamples;
    std::vector<LiveSample> received_;
    std::shared_ptr<StreamingEstimator> estimator_;
    LiveReestimator* reestimator_;
    bool reestimateFinishes_ = false;  ///< the running re-estimate was asked to finish (the session had ended)
    bool viewsDirty_ = false;
    std::shared_ptr<const Result> lastResult_;
    QString summaryLine_;  ///< the live figures' one line (over the live path, in the status bar)
    QString lastPort_;
    QString recordingPath_;  ///< the .mtb being recorded (or pending for the next session)
    QString lastRecordingPath_;  ///< the last one handed on, which a reconnect continues
    bool recordingActive_ = false;
    bool recordingStopAsked_ = false;        ///< by the user, through stopRecording()
    bool recordingCutBySessionEnd_ = false;  ///< a reconnect after a vanished port continues it
    bool sessionRecordedFromStart_ = false;  ///< every received sample is in a recording
    bool samplesSaved_ = false;              ///< saveSamplesTo() wrote them
};

/// "MTi-<device id>-2026-11-25-1432.mtb" ("MTi-2026-..." before a device answered).
QString defaultRecordingName(const QString& deviceId, const QDateTime& when);

/// Where a recording interrupted by a vanished port continues: "walk.mtb" -> "walk-2.mtb", or
/// the next number whose .mtb and .csv do not exist yet.
QString continuationPath(const QString& mtbPath);

}  // namespace footpath
