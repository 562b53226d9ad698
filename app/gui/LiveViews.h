#pragma once

#include "DeviceTypes.h"
#include "Result.h"
#include "nav/Parameters.h"

#include <QElapsedTimer>
#include <QObject>

#include <memory>
#include <vector>

class QLabel;
class QTabWidget;
class QWidget;

namespace footpath {

class SignalPlots;
class StanceFlagsPlot;
class TrajectoryView2D;
class TrajectoryView3D;

/// The views of a live session: the path estimated so far in 2D and 3D, the last seconds of
/// signals with the stance shading, and the stance detector's lanes for the same seconds. They
/// sit in two tab widgets that LivePanel shows itself or hands to the workspace's central area.
///
/// The signal window ends at the newest sample while the estimate ends latency_s earlier, so
/// the lanes and shading visibly trail the signals by the detector's look-ahead.
class LiveViews : public QObject {
    Q_OBJECT
public:
    /// Seconds of signals and lanes shown.
    static constexpr double kWindow_s = 10.0;

    explicit LiveViews(QWidget* parent);

    QTabWidget* trajectoryTabs() const { return trajectoryTabs_; }
    QTabWidget* signalTabs() const { return signalTabs_; }
    TrajectoryView2D* trajectory2D() const { return trajectory2D_; }
    TrajectoryView3D* trajectory3D() const { return trajectory3D_; }
    SignalPlots* signalPlots() const { return signals_; }
    StanceFlagsPlot* stanceFlags() const { return flags_; }

    /// Empties every view for a new session.
    void clear();
    /// A notice in the middle of every view saying why it is empty ("Not connected: choose a
    /// port and Connect"); an empty text hides it.
    void setNotice(const QString& text);
    QString notice() const { return notice_; }
    /// The live session's figures in a line at the top of the path views, where the user looks
    /// while walking (the workspace's summary is of the recorded walk); empty hides it.
    void setSummaryLine(const QString& text);
    QString summaryLine() const;
    /// The label showing the notice over `view` (one of the four views).
    QLabel* noticeLabel(QWidget* view) const;
    /// Thresholds and the window of the std of |a| in the lanes' input rows.
    void setParameters(const Parameters& params);

    /// Shows the last kWindow_s of `samples` and of `estimate`.
    void showSignals(const std::vector<LiveSample>& samples, const Result& estimate);
    /// Shows the whole path of `estimate` in the trajectory views and returns the path they
    /// keep, carrying `warnings` (the plausibility checks of the estimate so far) for the summary.
    /// The kept path grows in place: only the samples estimated since the last call are appended
    /// (a causal estimate never changes what it has estimated), so the pointer returned stays the
    /// same until restartPath(). Drawing a long walk is still slow, so this skips (and returns
    /// null) until five times the last update's duration has passed.
    std::shared_ptr<const Result> showPath(const Result& estimate, std::vector<PlausibilityWarning> warnings,
                                           bool force = false);
    /// The estimate starts again (new parameters, new session): the next showPath() starts a new
    /// path; holders of the old one keep it as it was.
    void restartPath();

private:
    TrajectoryView2D* trajectory2D_;
    TrajectoryView3D* trajectory3D_;
    SignalPlots* signals_;
    StanceFlagsPlot* flags_;
    QTabWidget* trajectoryTabs_;
    QTabWidget* signalTabs_;
    std::vector<QLabel*> noticeLabels_;  ///< one over each view
    std::vector<QLabel*> summaryLabels_;  ///< one in each path view
    QString notice_;
    std::shared_ptr<Result> path_;  ///< what the trajectory views show, grown by showPath()
    QElapsedTimer sincePathUpdate_;
    qint64 lastPathUpdateCost_ms_ = 0;
};

/// The per-sample part of `result` from the first sample at or after from_s on (steps and
/// summary are not copied).
Result resultWindow(const Result& result, double from_s);

/// What the trajectory views draw of `result`: times, positions, velocities, stance flags and
/// steps; the other per-sample vectors stay empty.
Result pathOnly(const Result& result);

/// Brings `path` (a pathOnly() of an earlier state of `result`) up to `result`: its per-sample
/// vectors get the samples after their end appended, its steps and summary are replaced.
void appendPath(Result& path, const Result& result);

}  // namespace footpath
