// A slider move in the real window on a 30-minute 100 Hz walk, end to end: from the slider's value
// change to the re-estimate on screen. Issue 14's target: under 100 ms.
//
// The window runs offscreen (QT_QPA_PLATFORM=offscreen unless set otherwise) at 1600 x 1000 with
// the walk opened as a user opens it (a CSV file). Each iteration moves the detector's adaptive
// threshold slider to and fro, as a drag does, and waits until
//   - the re-estimate has arrived (MainWindow::resultShown),
//   - every visible view of the recorded walk has replotted (of the signals, detector, states and
//     2D path views, the tabs in front; the views replot a hidden tab when it is brought to the
//     front, not on every change), and
//   - the window has then painted what the user sees (the visible tabs, the summary, the panel).
// Reported: the whole time (the benchmark's time) and its two parts as counters: estimate_ms, from
// the value change to the result's arrival on the GUI thread (mostly the pipeline, in core/), and
// views_ms, from the result's arrival to the painted window. The argument picks the signal tab in
// front: 0 the signals, 1 the stance detector, 2 the states.
//
//   build/bench/bench_window --benchmark_filter=SliderMove
//
// BM_LivePathRefresh: the live path views' refresh near the end of the same walk.
// BM_PathReplot: the 2D path view's redraw of that walk's estimate (argument 1: with the ghost).
#include "SimulatedWalks.h"

#include "AnalysisSession.h"
#include "AppSettings.h"
#include "DeferredReplot.h"
#include "LiveViews.h"
#include "MainWindow.h"
#include "Recorder.h"
#include "TrajectoryView2D.h"
#include "nav/Pipeline.h"
#include "nav/BulkAllocator.h"
#include "nav/StreamingEstimator.h"

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QHBoxLayout>
#include <QTimer>
#include <QMap>
#include <QSlider>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <qcustomplot.h>

#include <algorithm>

#include <sys/resource.h>
#include <cstdio>
#include <functional>
#include <memory>
#include <stdexcept>

using namespace footpath;

namespace {

const QString kSlider = QStringLiteral("slider_zv_adapt_fraction");

/// The views a parameter change redraws, by object name.
const QStringList& recordedViews()
{
    static const QStringList names{QStringLiteral("signalPlots"), QStringLiteral("stanceFlags"),
                                   QStringLiteral("statePlots"), QStringLiteral("trajectory2D")};
    return names;
}

/// Watches the window: when the result arrived, when each view's plot last replotted and whether
/// the window has been painted since.
class RepaintWatch : public QObject {
public:
    explicit RepaintWatch(MainWindow& window) : window_(window)
    {
        clock_.start();
        QObject::connect(window.session(), &AnalysisSession::estimatingChanged, this, [this](bool running) {
            if (!running)
                resultArrived_ms_ = now_ms();  // emitted just before resultChanged
        });
        QObject::connect(&window, &MainWindow::resultShown, this, [this] {
            shown_ = true;
            resultShown_ms_ = now_ms();
        });
        for (const QString& name : recordedViews()) {
            auto* view = window.findChild<QWidget*>(name);
            auto* plot = view ? view->findChild<QCustomPlot*>() : nullptr;
            if (!plot)
                throw std::runtime_error("no plot in the view " + name.toStdString());
            plots_.push_back(plot);
            QObject::connect(plot, &QCustomPlot::afterReplot, this, [this, plot, name] {
                replotted_.insert(plot);
                replot_ms_[name] += plot->replotTime();
            });
            // A view may redraw only the layers a new estimate changed (the signal rows' bands).
            if (auto* deferred = plot->findChild<DeferredReplot*>(QString(), Qt::FindDirectChildrenOnly))
                QObject::connect(deferred, &DeferredReplot::layersReplotted, this, [this, plot, name](double ms) {
                    replotted_.insert(plot);
                    replot_ms_[name] += ms;
                });
        }
        window.installEventFilter(this);
    }

    void reset()
    {
        shown_ = false;
        paintedAfterReplots_ = false;
        replotted_.clear();
        replot_ms_.clear();
        resultArrived_ms_ = -1.0;
        resultShown_ms_ = -1.0;
    }
    double now_ms() const { return static_cast<double>(clock_.nsecsElapsed()) / 1e6; }
    double resultArrived_ms() const { return resultArrived_ms_; }
    double resultShown_ms() const { return resultShown_ms_; }
    /// Milliseconds each view's plot spent replotting since the last reset.
    const QMap<QString, double>& replot_ms() const { return replot_ms_; }
    bool allReplotted() const
    {
        return shown_ && std::all_of(plots_.begin(), plots_.end(), [this](QCustomPlot* plot) {
                   return !plot->isVisible() || replotted_.contains(plot);
               });
    }
    bool done() const { return paintedAfterReplots_; }
    void setOnDone(std::function<void()> onDone) { onDone_ = std::move(onDone); }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        // The window paints every dirty widget in one UpdateRequest; the one after the last replot
        // puts the new plots on screen.
        if (watched == &window_ && event->type() == QEvent::UpdateRequest && allReplotted() && !paintedAfterReplots_) {
            paintedAfterReplots_ = true;
            if (onDone_)
                onDone_();  // an event loop quit now returns once this paint is done
        }
        return false;
    }

private:
    MainWindow& window_;
    QElapsedTimer clock_;
    std::vector<QCustomPlot*> plots_;
    QSet<QCustomPlot*> replotted_;
    bool shown_ = false;
    bool paintedAfterReplots_ = false;
    double resultArrived_ms_ = -1.0;
    double resultShown_ms_ = -1.0;
    QMap<QString, double> replot_ms_;
    std::function<void()> onDone_;
};

/// The window with the walk open, kept for all benchmarks (created on first use, destroyed before
/// the application object).
struct Workspace {
    QTemporaryDir dir;
    AppSettings settings{QStringLiteral("FootpathBench"), QStringLiteral("bench_window")};
    MainWindow window{settings};
    std::unique_ptr<RepaintWatch> watch;

    Workspace()
    {
        std::vector<LiveSample> samples;
        for (const ImuSample& imu : thirtyMinuteWalk().samples)
            samples.push_back(LiveSample{imu, {}, {}});
        const QString path = dir.filePath(QStringLiteral("thirty-minutes.csv"));
        if (const QString error = writeSamplesCsv(path, samples); !error.isEmpty())
            throw std::runtime_error(error.toStdString());
        window.resize(1600, 1000);
        window.show();
        watch = std::make_unique<RepaintWatch>(window);
        watch->reset();
        window.openRecording(path);
        waitUntilPainted(120000);
    }

    /// Runs the event loop until the window shows the re-estimate; false on timeout. Blocks in the
    /// event loop (no polling), so the pipeline's thread has the other core to itself.
    bool waitUntilPainted(int timeout_ms)
    {
        QEventLoop loop;
        watch->setOnDone([&loop] { loop.quit(); });
        QTimer::singleShot(timeout_ms, &loop, [&loop] { loop.exit(1); });
        const bool painted = watch->done() || loop.exec() == 0;
        watch->setOnDone({});
        return painted;
    }
};

long minorPageFaults()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

std::unique_ptr<Workspace>& workspaceHolder()
{
    static std::unique_ptr<Workspace> workspace;
    return workspace;
}

Workspace& workspace()
{
    if (!workspaceHolder())
        workspaceHolder() = std::make_unique<Workspace>();
    return *workspaceHolder();
}

void BM_SliderMove(benchmark::State& state)
{
    Workspace& space = workspace();
    static const char* const tabs[] = {"signals", "detector", "states"};
    space.window.showView(QString::fromLatin1(tabs[state.range(0)]));
    auto* slider = space.window.findChild<QSlider*>(kSlider);
    if (!slider || !slider->isEnabled()) {
        state.SkipWithError("the slider is missing or disabled");
        return;
    }
    const int home = slider->value();
    const int away = home + std::max(1, (slider->maximum() - slider->minimum()) / 50);
    QCoreApplication::processEvents();  // the tab switch's own paint is not part of the move
    double estimate_ms = 0.0, views_ms = 0.0, handOver_ms = 0.0, pipeline_ms = 0.0;
    QMap<QString, double> replot_ms;
    const long faultsBefore = minorPageFaults();
    for (auto _ : state) {
        space.watch->reset();
        const double start_ms = space.watch->now_ms();
        slider->setValue(slider->value() == home ? away : home);
        if (!space.waitUntilPainted(60000)) {
            state.SkipWithError("the re-estimate did not reach the screen within a minute");
            return;
        }
        const double end_ms = space.watch->now_ms();
        state.SetIterationTime((end_ms - start_ms) / 1000.0);
        estimate_ms += space.watch->resultArrived_ms() - start_ms;
        pipeline_ms += 1000.0 * space.window.session()->result()->summary.runtime_s;
        views_ms += end_ms - space.watch->resultArrived_ms();
        handOver_ms += space.watch->resultShown_ms() - space.watch->resultArrived_ms();
        for (auto it = space.watch->replot_ms().begin(); it != space.watch->replot_ms().end(); ++it)
            replot_ms[it.key()] += it.value();
    }
    // Where the views' time goes: handing the result to every view, then each plot's replots.
    state.counters["handover_ms"] = benchmark::Counter(handOver_ms, benchmark::Counter::kAvgIterations);
    for (auto it = replot_ms.begin(); it != replot_ms.end(); ++it)
        state.counters[("replot_" + it.key()).toStdString() + "_ms"] =
            benchmark::Counter(it.value(), benchmark::Counter::kAvgIterations);
    state.counters["estimate_ms"] = benchmark::Counter(estimate_ms, benchmark::Counter::kAvgIterations);
    state.counters["views_ms"] = benchmark::Counter(views_ms, benchmark::Counter::kAvgIterations);
    state.counters["pipeline_ms"] = benchmark::Counter(pipeline_ms, benchmark::Counter::kAvgIterations);
    // Pages the kernel had to map (and zero) for the moves, all threads: memory not reused.
    state.counters["page_faults"] =
        benchmark::Counter(static_cast<double>(minorPageFaults() - faultsBefore), benchmark::Counter::kAvgIterations);
    state.counters["samples"] = static_cast<double>(thirtyMinuteWalk().samples.size());
}
BENCHMARK(BM_SliderMove)->Arg(0)->Arg(1)->Arg(2)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(10);

/// A live session's path refresh near the end of the 30-minute walk: one more second estimated,
/// then the path views updated and painted (LiveViews::showPath, forced, and the event loop until
/// idle). The views are shown at 1600 x 1000 with the 2D path in front.
///
///   build/bench/bench_window --benchmark_filter=LivePathRefresh
void BM_LivePathRefresh(benchmark::State& state)
{
    const std::vector<ImuSample>& samples = thirtyMinuteWalk().samples;
    Parameters params;
    params.estimator = static_cast<int>(EstimatorKind::Ekf);  // live runs the filter
    StreamingEstimator estimator(params);
    const std::size_t oneSecond = 100, start = samples.size() - 60 * oneSecond;
    std::size_t next = 0;
    for (; next < start; ++next)
        estimator.push(samples[next]);
    QWidget window;
    auto* layout = new QHBoxLayout(&window);
    LiveViews views(&window);
    layout->addWidget(views.trajectoryTabs());
    layout->addWidget(views.signalTabs());
    window.resize(1600, 1000);
    window.show();
    views.showPath(estimator.result(), {}, true);
    QCoreApplication::processEvents();
    for (auto _ : state) {
        for (const std::size_t end = next + oneSecond; next < end && next < samples.size(); ++next)
            estimator.push(samples[next]);
        QElapsedTimer clock;
        clock.start();
        views.showPath(estimator.result(), {}, true);
        QCoreApplication::processEvents();  // the deferred replot and the paint
        state.SetIterationTime(static_cast<double>(clock.nsecsElapsed()) / 1e9);
    }
    state.counters["path_samples"] = static_cast<double>(estimator.result().time_s.size());
}
BENCHMARK(BM_LivePathRefresh)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(50);

/// The 2D path view's redraw of the 30-minute walk's estimate, the path coloured by time with its
/// stance markers, at 800 x 900; argument 1 adds the ghost (the same path: the run before).
///
///   build/bench/bench_window --benchmark_filter=PathReplot
void BM_PathReplot(benchmark::State& state)
{
    static const auto result = std::make_shared<const Result>(runPipeline(thirtyMinuteWalk(), Parameters()).result);
    TrajectoryView2D view;
    view.resize(800, 900);
    view.show();
    view.setResult(result);
    if (state.range(0) == 1)
        view.setGhostPath(result->position_m);
    QCoreApplication::processEvents();
    auto* plot = view.findChild<QCustomPlot*>();
    for (auto _ : state)
        plot->replot(QCustomPlot::rpImmediateRefresh);
    state.counters["path_samples"] = static_cast<double>(result->position_m.size());
}
BENCHMARK(BM_PathReplot)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv)
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true);  // the benchmark's settings never touch a user's
    footpath::keepFreedMemoryForReruns();      // as the application does
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    try {
        benchmark::RunSpecifiedBenchmarks();
    } catch (const std::exception& error) {
        std::fprintf(stderr, "bench_window: %s\n", error.what());
        return 1;
    }
    workspaceHolder().reset();  // widgets go before the application object
    benchmark::Shutdown();
    return 0;
}
