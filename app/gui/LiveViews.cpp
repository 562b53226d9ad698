#include "LiveViews.h"

#include "SignalPlots.h"
#include "StanceFlagsPlot.h"
#include "TrajectoryView2D.h"
#include "TrajectoryView3D.h"

#include <QEvent>
#include <QLabel>
#include <QTabWidget>

#include <algorithm>

namespace footpath {

namespace {

constexpr qint64 kPathCostFactor = 5;  // path updates take at most a fifth of the GUI thread

std::size_t firstAtOrAfter(const std::vector<double>& times, double from_s)
{
    return static_cast<std::size_t>(std::lower_bound(times.begin(), times.end(), from_s) - times.begin());
}

template <typename T>
std::vector<T> tailFrom(const std::vector<T>& values, std::size_t first)
{
    return first < values.size() ? std::vector<T>(values.begin() + static_cast<std::ptrdiff_t>(first), values.end())
                                 : std::vector<T>();
}

/// A label over its parent view that places itself again whenever the view is resized or shown.
class ViewNote : public QLabel {
public:
    explicit ViewNote(QWidget* view, const QString& style) : QLabel(view)
    {
        setWordWrap(true);
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setStyleSheet(style);
        view->installEventFilter(this);
        hide();
    }

    virtual void place() = 0;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (watched == parentWidget() && (event->type() == QEvent::Resize || event->type() == QEvent::Show))
            place();
        return false;
    }

    /// The label's height at this width (wrapped text), or its one-line height.
    int heightAt(int width) const { return heightForWidth(width) > 0 ? heightForWidth(width) : sizeHint().height(); }
};

/// Centred over its view: why the view is empty.
class CentredNotice : public ViewNote {
public:
    explicit CentredNotice(QWidget* view)
        : ViewNote(view, QStringLiteral("QLabel { background: rgba(255, 255, 255, 230); color: #303030; "
                                        "border: 1px solid #a0a0a0; border-radius: 6px; padding: 12px; }"))
    {
        setObjectName(QStringLiteral("liveNotice"));
        setAlignment(Qt::AlignCenter);
        QFont bigger = font();
        bigger.setPointSizeF(bigger.pointSizeF() * 1.25);
        setFont(bigger);
    }

    void place() override
    {
        const QWidget* view = parentWidget();
        const int width = std::min(view->width() - 20, 520);
        const int height = heightAt(width);
        setGeometry((view->width() - width) / 2, (view->height() - height) / 2, width, height);
        raise();
    }
};

/// In the top left corner of its view (over the plot's margin): one line where the view is wide
/// enough, wrapped where it is not, never cut at the view's edge.
class CornerNote : public ViewNote {
public:
    explicit CornerNote(QWidget* view)
        : ViewNote(view, QStringLiteral("QLabel { background: rgba(255, 255, 255, 215); color: #202020; "
                                        "border: 1px solid #c0c0c0; border-radius: 3px; padding: 2px 6px; }"))
    {
        setObjectName(QStringLiteral("liveSummaryLine"));
    }

    void place() override
    {
        const QWidget* view = parentWidget();
        // The text, the padding and the frame, and a little for the rich-text layout that wraps early.
        const int oneLine = fontMetrics().horizontalAdvance(text()) + 2 * (margin() + 8) + 12;
        const int width = std::max(40, std::min(oneLine, view->width() - 16));
        setGeometry(8, 6, width, heightAt(width));
        raise();
    }
};

}  // namespace

Result resultWindow(const Result& result, double from_s)
{
    const std::size_t first = firstAtOrAfter(result.time_s, from_s);
    Result window;
    window.time_s = tailFrom(result.time_s, first);
    window.position_m = tailFrom(result.position_m, first);
    window.velocity_mps = tailFrom(result.velocity_mps, first);
    window.rollPitchYaw_rad = tailFrom(result.rollPitchYaw_rad, first);
    window.gyroBias_radps = tailFrom(result.gyroBias_radps, first);
    window.accBias_mps2 = tailFrom(result.accBias_mps2, first);
    window.errorStd = tailFrom(result.errorStd, first);
    window.flags.c1 = tailFrom(result.flags.c1, first);
    window.flags.c2 = tailFrom(result.flags.c2, first);
    window.flags.c3 = tailFrom(result.flags.c3, first);
    window.flags.c = tailFrom(result.flags.c, first);
    window.flags.stance = tailFrom(result.flags.stance, first);
    window.flags.logStatistic = tailFrom(result.flags.logStatistic, first);
    window.flags.logThreshold = tailFrom(result.flags.logThreshold, first);
    for (const PlausibilityWarning& warning : result.warnings)
        if (warning.end_s >= from_s)
            window.warnings.push_back(warning);
    return window;
}

Result pathOnly(const Result& result)
{
    Result path;
    appendPath(path, result);
    return path;
}

void appendPath(Result& path, const Result& result)
{
    const std::size_t from = path.time_s.size();
    const auto appendTail = [from](auto& to, const auto& values) {
        if (from < values.size())
            to.insert(to.end(), values.begin() + static_cast<std::ptrdiff_t>(from), values.end());
    };
    appendTail(path.time_s, result.time_s);
    appendTail(path.position_m, result.position_m);
    appendTail(path.velocity_mps, result.velocity_mps);
    appendTail(path.flags.stance, result.flags.stance);
    path.steps = result.steps;  // a few per second of walk: cheap, and the tail's may be decided late
    path.summary = result.summary;
}

LiveViews::LiveViews(QWidget* parent)
    : QObject(parent),
      trajectory2D_(new TrajectoryView2D),
      trajectory3D_(new TrajectoryView3D),
      signals_(new SignalPlots),
      flags_(new StanceFlagsPlot),
      trajectoryTabs_(new QTabWidget(parent)),
      signalTabs_(new QTabWidget(parent))
{
    // Object names tell these apart from the workspace's own views of a recorded walk.
    trajectory2D_->setObjectName(QStringLiteral("liveTrajectory2D"));
    trajectory3D_->setObjectName(QStringLiteral("liveTrajectory3D"));
    signals_->setObjectName(QStringLiteral("liveSignals"));
    flags_->setObjectName(QStringLiteral("liveStanceFlags"));
    trajectoryTabs_->setTabToolTip(trajectoryTabs_->addTab(trajectory2D_, tr("Live 2D")),
                                   tr("The live session's path seen from above, as it grows"));
    trajectoryTabs_->setTabToolTip(trajectoryTabs_->addTab(trajectory3D_, tr("Live 3D")),
                                   tr("The live session's path in three dimensions, as it grows"));
    signalTabs_->setTabToolTip(signalTabs_->addTab(signals_, tr("Live IMU")),
                               tr("Live signals: the live session's last seconds of sensor signals"));
    signalTabs_->setTabToolTip(signalTabs_->addTab(flags_, tr("Live stance")),
                               tr("Live stance detector: the live session's detector over its last seconds"));
    flags_->setParameters(Parameters{});
    for (QWidget* view : {static_cast<QWidget*>(trajectory2D_), static_cast<QWidget*>(trajectory3D_),
                          static_cast<QWidget*>(signals_), static_cast<QWidget*>(flags_)})
        noticeLabels_.push_back(new CentredNotice(view));
    for (QWidget* view : {static_cast<QWidget*>(trajectory2D_), static_cast<QWidget*>(trajectory3D_)})
        summaryLabels_.push_back(new CornerNote(view));
    sincePathUpdate_.start();
}

void LiveViews::setNotice(const QString& text)
{
    notice_ = text;
    for (QLabel* label : noticeLabels_) {
        label->setText(text);
        label->setVisible(!text.isEmpty());
        static_cast<CentredNotice*>(label)->place();
    }
}

void LiveViews::setSummaryLine(const QString& text)
{
    for (QLabel* label : summaryLabels_) {
        label->setText(text);
        static_cast<CornerNote*>(label)->place();
        label->setVisible(!text.isEmpty());
    }
}

QString LiveViews::summaryLine() const
{
    return summaryLabels_.empty() ? QString() : summaryLabels_.front()->text();
}

QLabel* LiveViews::noticeLabel(QWidget* view) const
{
    for (QLabel* label : noticeLabels_)
        if (label->parentWidget() == view)
            return label;
    return nullptr;
}

void LiveViews::clear()
{
    trajectory2D_->clear();
    trajectory3D_->clear();
    signals_->setRecording(nullptr);
    flags_->setRecording(nullptr);
    path_.reset();
    lastPathUpdateCost_ms_ = 0;
}

void LiveViews::setParameters(const Parameters& params)
{
    flags_->setParameters(params);
}

void LiveViews::showSignals(const std::vector<LiveSample>& samples, const Result& estimate)
{
    if (samples.empty())
        return;
    const double newest_s = samples.back().imu.time_s;
    const double from_s = newest_s - kWindow_s;
    const auto first = std::lower_bound(samples.begin(), samples.end(), from_s,
                                        [](const LiveSample& s, double t) { return s.imu.time_s < t; });
    auto recording = std::make_shared<Recording>();
    recording->source = tr("live").toStdString();
    recording->samples.reserve(static_cast<std::size_t>(samples.end() - first));
    for (auto it = first; it != samples.end(); ++it)
        recording->samples.push_back(it->imu);
    auto window = std::make_shared<const Result>(resultWindow(estimate, from_s));
    signals_->setRecording(recording);
    signals_->setResult(window);
    flags_->setRecording(recording);
    flags_->setResult(window);
    // A whole window even in the first seconds, so the plots scroll instead of stretching.
    signals_->setTimeRange(from_s, newest_s);
    flags_->setTimeRange(from_s, newest_s);
}

std::shared_ptr<const Result> LiveViews::showPath(const Result& estimate, std::vector<PlausibilityWarning> warnings,
                                                  bool force)
{
    if (!force && sincePathUpdate_.elapsed() < kPathCostFactor * lastPathUpdateCost_ms_)
        return {};
    QElapsedTimer cost;
    cost.start();
    if (!path_ || path_->time_s.size() > estimate.time_s.size())
        path_ = std::make_shared<Result>();  // not a continuation of what is shown: start afresh
    appendPath(*path_, estimate);
    path_->warnings = std::move(warnings);
    trajectory2D_->followResult(path_);
    trajectory3D_->followResult(path_);
    lastPathUpdateCost_ms_ = cost.elapsed();
    sincePathUpdate_.restart();
    return path_;
}

void LiveViews::restartPath()
{
    path_.reset();
}

}  // namespace footpath
