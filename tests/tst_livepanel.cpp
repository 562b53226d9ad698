// The live panel against the emulator on a pseudo-terminal, with seeded faults (dropped and
// damaged messages, junk between frames). The emulator's log of what it sent is the truth: the
// panel received every intact message exactly once with its values, counted the lost ones, its
// recordings re-open with exactly the samples it received while they ran, its causal estimate
// trails the newest sample by the displayed latency and ends equal to the offline analysis of
// the same samples, and a vanished port leads to a reconnect offer that continues the recording.
#include "LivePanel.h"
#include "LiveTestSupport.h"
#include "LiveViews.h"
#include "ReconnectOffer.h"
#include "SignalPlots.h"
#include "StanceFlagsPlot.h"
#include "TrajectoryView2D.h"
#include "io/Import.h"
#include "nav/Pipeline.h"
#include "nav/StreamingEstimator.h"

#include <QApplication>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QStandardPaths>
#include <qcustomplot.h>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
#include <QtTest>

#include <algorithm>

using namespace footpath;
using namespace livetest;

class TestLivePanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void latencyFollowsParameters();
    void continuationPathsCountUp();
    void receivesRecordsAndEstimatesCausally();
    void parameterChangeMidStreamReestimatesOffTheGuiThread();
    void notShownCountsWhatABusyWindowMissed();
    void recordsFromFirstSample();
    void offersReconnectWhenPortVanishes();
    void reconnectAsksBeforeDroppingUnsavedSamples();
    void viewsSayNotConnected();
    void badPortSaysNotConnectedAndShowsTheError();
    void defaultRecordingNameHasDeviceAndTime();
    void unrecordedSessionCanBeSavedAfterDisconnect();
};

namespace {

const QStringList kFaults = {QStringLiteral("--seed"),       QStringLiteral("5"),    QStringLiteral("--drop-rate"),
                             QStringLiteral("0.01"),         QStringLiteral("--corrupt-rate"), QStringLiteral("0.01"),
                             QStringLiteral("--junk-rate"),  QStringLiteral("0.02"), QStringLiteral("--speed"),
                             QStringLiteral("10")};
/// The port goes away after 3 s of streaming and comes back 1 s later (a USB plug pulled).
const QStringList kUnplugAndReplug = {QStringLiteral("--disconnect-after"), QStringLiteral("3"),
                                      QStringLiteral("--replug-after"), QStringLiteral("1")};

bool sameValues(const ImuSample& a, const ImuSample& b)
{
    return a.acc_mps2 == b.acc_mps2 && a.gyr_radps == b.gyr_radps;
}

/// The received samples are the intact sent messages from the first received to the last
/// received one, in order, each once, with the device's values; returns the messages lost between.
std::uint64_t checkAgainstSent(const std::vector<LiveSample>& received, const std::vector<Sent>& sent)
{
    if (received.empty() || !received.front().packetCounter || !received.back().packetCounter) {
        qWarning("no samples, or samples without a packet counter");
        return ~std::uint64_t(0);
    }
    const unsigned first = *received.front().packetCounter, last = *received.back().packetCounter;
    std::vector<Sent> expected;
    std::uint64_t lost = 0;
    for (const Sent& s : sent) {
        if (s.counter < first || s.counter > last)
            continue;
        if (s.intact())
            expected.push_back(s);
        else
            ++lost;
    }
    [&] {
        QCOMPARE(received.size(), expected.size());
        for (std::size_t k = 0; k < received.size(); ++k) {
            QCOMPARE(unsigned(received[k].packetCounter.value_or(0)), expected[k].counter);
            const ImuSample& imu = received[k].imu;
            for (int i = 0; i < 3; ++i) {
                QCOMPARE(imu.acc_mps2[i], expected[k].values[std::size_t(i)]);  // bit for bit
                QCOMPARE(imu.gyr_radps[i], expected[k].values[std::size_t(3 + i)]);
            }
        }
    }();
    return lost;
}

/// The recording holds exactly the received samples from some point on to the last one.
void checkRecordingIsReceivedTail(const QString& mtb, const std::vector<LiveSample>& received)
{
    const ImportResult imported = importRecording(mtb.toStdString());
    QVERIFY2(imported.ok(), imported.ok() ? "" : imported.error->message.c_str());
    const std::vector<ImuSample>& recorded = imported.recording.samples;
    QVERIFY(!recorded.empty() && recorded.size() <= received.size());
    const std::size_t offset = received.size() - recorded.size();
    QVERIFY2(sameValues(recorded.front(), received[offset].imu), "the recording is not the tail of what was received");
    for (std::size_t k = 0; k < recorded.size(); ++k) {
        const ImuSample& a = recorded[k];
        const ImuSample& b = received[offset + k].imu;
        QVERIFY2(sameValues(a, b), qPrintable(QStringLiteral("recorded sample %1 differs").arg(k)));
        QVERIFY(std::abs((a.time_s - recorded.front().time_s) - (b.time_s - received[offset].imu.time_s)) < 1e-9);
    }
}

/// Answers the next message box with `button` once it is shown (polling the modal widget, as a
/// user's click would come), and keeps its text in `*text`.
void answerNextQuestion(QMessageBox::StandardButton button, QString* text)
{
    auto* poll = new QTimer;
    poll->setInterval(20);
    QObject::connect(poll, &QTimer::timeout, poll, [poll, button, text] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box)
            return;
        *text = box->text();
        box->button(button)->click();
        poll->deleteLater();
    });
    poll->start();
}

Recording asRecording(const std::vector<LiveSample>& received)
{
    Recording recording;
    for (const LiveSample& sample : received)
        recording.samples.push_back(sample.imu);
    return recording;
}

}  // namespace

void TestLivePanel::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);  // the remembered recording folder stays out of the user's settings
    if (!QFileInfo::exists(QStringLiteral("/dev/ptmx")))
        QSKIP("no pseudo-terminals on this system (/dev/ptmx)");
}

void TestLivePanel::latencyFollowsParameters()
{
    LivePanel panel;
    // The default detector: half the statistic window, half the adaptive window and the minimum
    // stance duration (a stance run is held until it has lasted that long).
    const Parameters defaults;
    QCOMPARE(panel.latency_s(), defaults.zv_window_s / 2.0 + defaults.zv_adapt_window_s / 2.0 + defaults.zv_min_stance_s);
    QVERIFY(panel.latency_s() > 0.5);  // the adaptive window dominates
    Parameters params = footpath::guo2015Parameters();
    params.window_half_s = 0.2;
    params.median_window_s = 0.3;
    panel.setParameters(params);
    QCOMPARE(panel.latency_s(), 0.2 + 0.15);
}

void TestLivePanel::continuationPathsCountUp()
{
    QTemporaryDir dir;
    const QString walk = dir.filePath(QStringLiteral("walk.mtb"));
    QCOMPARE(continuationPath(walk), dir.filePath(QStringLiteral("walk-2.mtb")));
    QCOMPARE(continuationPath(dir.filePath(QStringLiteral("walk-2.mtb"))), dir.filePath(QStringLiteral("walk-3.mtb")));
    QFile taken(dir.filePath(QStringLiteral("walk-2.csv")));
    QVERIFY(taken.open(QIODevice::WriteOnly));  // a CSV alone already takes the name
    QCOMPARE(continuationPath(walk), dir.filePath(QStringLiteral("walk-3.mtb")));
}

void TestLivePanel::receivesRecordsAndEstimatesCausally()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("ttyMTi0"));
    const QString log = dir.filePath(QStringLiteral("sent.csv"));
    Emulator emulator;
    const QString problem = emulator.start(link, log, kFaults + QStringList{QStringLiteral("--once")});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));

    LivePanel panel;
    panel.resize(600, 1200);
    panel.show();
    QSignalSpy identified(panel.session(), &DeviceSession::deviceIdentified);
    QSignalSpy started(panel.session(), &DeviceSession::recordingStarted);
    QSignalSpy ended(panel.session(), &DeviceSession::ended);
    QSignalSpy finished(&panel, &LivePanel::recordingFinished);
    QSignalSpy trajectory(&panel, &LivePanel::trajectoryUpdated);

    panel.connectTo(link);
    QTRY_VERIFY_WITH_TIMEOUT(identified.count() == 1, 15000);
    const QString mtb = dir.filePath(QStringLiteral("live.mtb"));
    panel.startRecordingTo(mtb);  // mid-stream: recorded from the next bytes on
    QTRY_VERIFY_WITH_TIMEOUT(started.count() == 1, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(panel.sampleCount() >= 1500, 30000);

    // Causal: the estimate ends at least the detector's windows (the latency without a held stance
    // run) and at most one latency plus a sample (or a lost packet's gap) before the newest sample.
    const StreamingEstimator& estimator = *panel.estimator();
    QVERIFY(estimator.aligned());
    const double newest_s = panel.receivedSamples().back().imu.time_s;
    const double lag_s = newest_s - estimator.result().time_s.back();
    const double windows_s = panel.latency_s() - Parameters().zv_min_stance_s;  // the panel runs the defaults
    QVERIFY2(lag_s > windows_s && lag_s < panel.latency_s() + 0.05,
             qPrintable(QStringLiteral("estimate lags %1 s, latency %2 s").arg(lag_s).arg(panel.latency_s())));
    QTRY_VERIFY_WITH_TIMEOUT(trajectory.count() >= 1, 30000);
    const auto* lanes = panel.views()->stanceFlags();
    QVERIFY(lanes->laneGraph(StanceFlagsPlot::Lane::Stance)->dataCount() > 0);
    const int shownSignals = panel.views()->signalPlots()->graph(SignalPlots::Channel::AccX)->dataCount();
    QVERIFY2(shownSignals > 500 && shownSignals <= 1001, qPrintable(QString::number(shownSignals)));  // 10 s at 100 Hz

    panel.disconnectDevice();
    QTRY_VERIFY_WITH_TIMEOUT(ended.count() == 1, 15000);
    QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 5000);
    QCOMPARE(finished.at(0).at(0).toString(), mtb);
    QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("live.csv"))));
    emulator.stop();

    const std::vector<LiveSample>& received = panel.receivedSamples();
    QCOMPARE(std::uint64_t(received.size()), panel.session()->counters().samplesReceived);
    const std::uint64_t lost = checkAgainstSent(received, readSentLog(log));
    QVERIFY2(lost >= 5, "the seed should drop and damage some messages");
    QCOMPARE(panel.session()->counters().packetsLost, lost);
    checkRecordingIsReceivedTail(mtb, received);

    // At the end the live estimate is the offline analysis of what was received.
    Parameters filterOnly;  // live runs the filter: the offline smoother's backward pass needs the whole walk
    filterOnly.estimator = static_cast<int>(EstimatorKind::Ekf);
    const PipelineOutput offline = runPipeline(asRecording(received), filterOnly);
    QVERIFY(offline.error.empty());
    const Result& live = estimator.result();
    QCOMPARE(live.time_s.size(), received.size());
    QVERIFY(live.position_m == offline.result.position_m);
    QVERIFY(live.flags.stance == offline.result.flags.stance);
    QCOMPARE(live.steps.size(), offline.result.steps.size());
    QVERIFY(panel.lastResult() && panel.lastResult()->position_m == offline.result.position_m);
}

void TestLivePanel::parameterChangeMidStreamReestimatesOffTheGuiThread()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("ttyMTi3"));
    Emulator emulator;
    const QString problem = emulator.start(link, dir.filePath(QStringLiteral("sent.csv")), kFaults + QStringList{QStringLiteral("--once")});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));

    LivePanel panel;
    QSignalSpy ended(panel.session(), &DeviceSession::ended);
    panel.connectTo(link);
    QTRY_VERIFY_WITH_TIMEOUT(panel.sampleCount() >= 1500 && panel.lastResult(), 30000);
    const StreamingEstimator* before = panel.estimator();
    Parameters changed;
    changed.zv_adapt_fraction = 0.35;
    panel.setParameters(changed);
    QVERIFY(panel.isReestimating());  // started, not run inside setParameters
    QCOMPARE(panel.estimator(), before);  // the old estimate goes on meanwhile
    QTRY_VERIFY_WITH_TIMEOUT(!panel.isReestimating(), 30000);
    QVERIFY(panel.estimator() != before);
    QCOMPARE(panel.estimator()->parameters(), changed);

    panel.disconnectDevice();
    QTRY_VERIFY_WITH_TIMEOUT(ended.count() == 1, 15000);
    emulator.stop();
    // The re-estimate took over and caught up: at the end it is the offline analysis of every
    // received sample with the new parameters, and so is the path the views show.
    Parameters filterOnly = changed;
    filterOnly.estimator = static_cast<int>(EstimatorKind::Ekf);
    const PipelineOutput offline = runPipeline(asRecording(panel.receivedSamples()), filterOnly);
    QVERIFY(offline.error.empty());
    QCOMPARE(panel.estimator()->result().time_s.size(), panel.receivedSamples().size());
    QVERIFY(panel.estimator()->result().position_m == offline.result.position_m);
    QVERIFY(panel.lastResult() && panel.lastResult()->position_m == offline.result.position_m);

    // A re-estimate cancelled by parameters the estimator refuses: the dock stops saying
    // "Re-estimating" at once; after the session nothing else would refresh it.
    const auto* state = panel.findChild<QLabel*>(QStringLiteral("liveEstimateState"));
    QVERIFY(state);
    Parameters another = changed;
    another.zv_adapt_fraction = 0.4;
    panel.setParameters(another);
    QVERIFY(panel.isReestimating());
    QVERIFY2(state->text().startsWith(QStringLiteral("Re-estimating")), qPrintable(state->text()));
    Parameters refused = another;
    refused.acc_min_mps2 = refused.acc_max_mps2 + 1.0;
    QVERIFY(!refused.validate().empty());
    panel.setParameters(refused);
    QVERIFY(!panel.isReestimating());
    QTest::qWait(200);  // the cancelled run ends meanwhile
    QVERIFY2(!state->text().startsWith(QStringLiteral("Re-estimating")), qPrintable(state->text()));
    // It says why there is no estimate, as the status line does, not "Aligning".
    QVERIFY2(state->text().startsWith(QStringLiteral("No live estimate: ")), qPrintable(state->text()));
    QCOMPARE(panel.estimator()->parameters(), refused);  // the cancelled run did not take over
}

void TestLivePanel::notShownCountsWhatABusyWindowMissed()
{
    // The display queue holds 2 s of samples at 5x speed (500 a second); the window is then
    // blocked for 4 s while the port goes on: the oldest samples are dropped from the queue, and
    // the dock's "Not shown" row appears with exactly how many the views never got.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("ttyMTi3"));
    Emulator emulator;
    const QString problem = emulator.start(link, QString(), {QStringLiteral("--speed"), QStringLiteral("5")});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));

    LivePanel panel;
    constexpr std::size_t kBound = 1000;
    panel.setDisplayQueueSamples(kBound);
    QSignalSpy ended(panel.session(), &DeviceSession::ended);
    const auto* notShown = panel.findChild<QLabel*>(QStringLiteral("liveNotShown"));
    QVERIFY(notShown);
    panel.connectTo(link);
    QTRY_VERIFY_WITH_TIMEOUT(panel.sampleCount() >= 500, 30000);
    QCOMPARE(panel.session()->counters().samplesNotShown, std::uint64_t(0));
    QVERIFY(notShown->isHidden());  // nothing dropped: no row

    QThread::msleep(4000);  // a busy window: no event is handled, the worker thread goes on receiving
    panel.disconnectDevice();
    QTRY_VERIFY_WITH_TIMEOUT(ended.count() == 1, 15000);
    const DeviceCounters counters = panel.session()->counters();
    QVERIFY2(counters.samplesNotShown > 0, "the queue did not overflow");
    // Every received sample was either shown or counted as not shown.
    QCOMPARE(counters.samplesReceived, std::uint64_t(panel.sampleCount()) + counters.samplesNotShown);
    QVERIFY(!notShown->isHidden());
    QCOMPARE(notShown->text(), QString::number(counters.samplesNotShown));

    // A new session starts from nothing dropped: the row goes again. (The unrecorded samples of
    // this one are let go when the panel asks.)
    panel.setDisplayQueueSamples(SessionSettings{}.displayQueueSamples);
    QString question;
    answerNextQuestion(QMessageBox::Discard, &question);
    QVERIFY(panel.connectTo(link));
    QVERIFY(question.contains(QStringLiteral("Save them before connecting again?")));
    QTRY_VERIFY_WITH_TIMEOUT(panel.sampleCount() >= 100, 30000);
    QTRY_VERIFY_WITH_TIMEOUT(notShown->isHidden(), 5000);
    QCOMPARE(panel.session()->counters().samplesNotShown, std::uint64_t(0));
    panel.disconnectDevice();
    QTRY_VERIFY_WITH_TIMEOUT(ended.count() == 2, 15000);
}

void TestLivePanel::recordsFromFirstSample()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("ttyMTi1"));
    const QString log = dir.filePath(QStringLiteral("sent.csv"));
    Emulator emulator;
    const QString problem = emulator.start(link, log, kFaults + QStringList{QStringLiteral("--once")});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));

    LivePanel panel;
    QSignalSpy ended(panel.session(), &DeviceSession::ended);
    QSignalSpy finished(&panel, &LivePanel::recordingFinished);
    const QString mtb = dir.filePath(QStringLiteral("first.mtb"));
    panel.startRecordingTo(mtb);  // before connecting: recorded from the first sample on
    panel.connectTo(link);
    QTRY_VERIFY_WITH_TIMEOUT(panel.sampleCount() >= 500, 30000);
    panel.disconnectDevice();
    QTRY_VERIFY_WITH_TIMEOUT(ended.count() == 1, 15000);
    QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 5000);
    QCOMPARE(finished.at(0).at(0).toString(), mtb);
    emulator.stop();
    const std::vector<LiveSample>& received = panel.receivedSamples();
    checkAgainstSent(received, readSentLog(log));
    QCOMPARE(importRecording(mtb.toStdString()).recording.samples.size(), received.size());
    checkRecordingIsReceivedTail(mtb, received);
}

void TestLivePanel::offersReconnectWhenPortVanishes()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("ttyMTi2"));
    const QString log = dir.filePath(QStringLiteral("sent.csv"));
    Emulator emulator;  // unplugged after 3 s of streaming, plugged in again 1 s later
    const QString problem = emulator.start(link, log, kFaults + kUnplugAndReplug);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));

    LivePanel panel;
    panel.show();
    QSignalSpy ended(panel.session(), &DeviceSession::ended);
    QSignalSpy finished(&panel, &LivePanel::recordingFinished);
    const QString mtb = dir.filePath(QStringLiteral("walk.mtb"));
    panel.startRecordingTo(mtb);
    panel.connectTo(link);
    QTRY_VERIFY_WITH_TIMEOUT(ended.count() == 1, 30000);
    QCOMPARE(ended.at(0).at(0).value<SessionEnd>(), SessionEnd::Vanished);
    QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 5000);

    // Everything received before the plug was pulled is in the panel and in the recording.
    const std::vector<LiveSample> beforeUnplug = panel.receivedSamples();
    checkAgainstSent(beforeUnplug, readSentLog(log));
    QCOMPARE(importRecording(mtb.toStdString()).recording.samples.size(), beforeUnplug.size());

    ReconnectOffer* offer = panel.reconnectOffer();
    QVERIFY(offer->isVisible());
    QVERIFY(!offer->reconnectButton()->isEnabled());  // the port is gone
    QTRY_VERIFY_WITH_TIMEOUT(offer->reconnectButton()->isEnabled(), 8000);
    offer->reconnectButton()->click();
    QVERIFY(!offer->isVisible());
    QTRY_VERIFY_WITH_TIMEOUT(ended.count() == 2, 30000);  // the replugged device vanishes again after 3 s
    QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 2, 5000);
    const QString continued = dir.filePath(QStringLiteral("walk-2.mtb"));
    QCOMPARE(finished.at(1).at(0).toString(), continued);
    QVERIFY(panel.sampleCount() > 250);
    QCOMPARE(importRecording(continued.toStdString()).recording.samples.size(), panel.sampleCount());
    checkRecordingIsReceivedTail(continued, panel.receivedSamples());
    QVERIFY(offer->isVisible());
}

void TestLivePanel::reconnectAsksBeforeDroppingUnsavedSamples()
{
    // Reconnect started a new session at 0 samples: the 600 the dock said were kept were gone,
    // without the question Connect asks.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("ttyMTi4"));
    Emulator emulator;  // unplugged after 3 s of streaming, plugged in again 1 s later
    const QString problem = emulator.start(link, QString(), kFaults + kUnplugAndReplug);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));

    LivePanel panel;
    panel.show();
    QSignalSpy ended(panel.session(), &DeviceSession::ended);
    QVERIFY(panel.connectTo(link));
    QTRY_VERIFY_WITH_TIMEOUT(ended.count() == 1, 30000);
    const std::size_t received = panel.sampleCount();
    QVERIFY(received > 100);
    QVERIFY(panel.hasUnsavedSamples());
    ReconnectOffer* offer = panel.reconnectOffer();
    QTRY_VERIFY_WITH_TIMEOUT(offer->reconnectButton()->isEnabled(), 8000);

    // Cancel keeps everything: the samples, the offer, no new session.
    QString question;
    answerNextQuestion(QMessageBox::Cancel, &question);
    offer->reconnectButton()->click();
    QVERIFY2(question.contains(QStringLiteral("%1 samples").arg(received)), qPrintable(question));
    QVERIFY2(question.contains(QStringLiteral("reconnecting")), qPrintable(question));
    QCOMPARE(panel.sampleCount(), received);
    QCOMPARE(panel.session()->state(), SessionState::Idle);
    QVERIFY(offer->isVisible());
    // Connect asks the same (it did before), and so does quitting the window (mayEndSession).
    answerNextQuestion(QMessageBox::Cancel, &question);
    QVERIFY(!panel.connectTo(link));
    QVERIFY2(question.contains(QStringLiteral("connecting again")), qPrintable(question));
    answerNextQuestion(QMessageBox::Cancel, &question);
    QVERIFY(!panel.mayEndSession(LivePanel::SessionEnding::Quit));
    QVERIFY2(question.contains(QStringLiteral("quitting")), qPrintable(question));
    QCOMPARE(panel.sampleCount(), received);

    // Discard: the user chose; the new session starts.
    answerNextQuestion(QMessageBox::Discard, &question);
    offer->reconnectButton()->click();
    QVERIFY(!offer->isVisible());
    QTRY_VERIFY_WITH_TIMEOUT(panel.session()->state() != SessionState::Idle, 5000);
    panel.disconnectDevice();
    QTRY_VERIFY_WITH_TIMEOUT(ended.count() == 2, 30000);
    emulator.stop();
}

void TestLivePanel::viewsSayNotConnected()
{
    LivePanel panel;
    panel.resize(900, 1200);
    panel.show();
    QVERIFY(panel.views()->notice().startsWith(QStringLiteral("Not connected: choose a port and Connect")));
    for (QWidget* view : {static_cast<QWidget*>(panel.views()->trajectory2D()), static_cast<QWidget*>(panel.views()->signalPlots())}) {
        QLabel* notice = panel.views()->noticeLabel(view);
        QVERIFY(notice);
        QVERIFY(notice->isVisible());
        QCOMPARE(notice->text(), panel.views()->notice());
        // Centred in the view, inside it.
        QVERIFY(view->rect().contains(notice->geometry()));
        QVERIFY(std::abs(notice->geometry().center().x() - view->rect().center().x()) <= 2);
    }
    QCOMPARE(panel.statusText(), QStringLiteral("Not connected"));
    QVERIFY(panel.errorText().isEmpty());
    // For looking at it: FOOTPATH_SCREENSHOT_DIR=/tmp/shots tst_livepanel viewsSayNotConnected
    if (const QString shots = qEnvironmentVariable("FOOTPATH_SCREENSHOT_DIR"); !shots.isEmpty())
        for (const QSize size : {QSize(1920, 1080), QSize(1280, 800)}) {
            panel.resize(size);
            QVERIFY(panel.grab().save(QDir(shots).filePath(QStringLiteral("live-not-connected-%1.png").arg(size.width()))));
        }
}

void TestLivePanel::badPortSaysNotConnectedAndShowsTheError()
{
    QTemporaryDir dir;
    LivePanel panel;
    panel.resize(600, 1000);
    panel.show();
    QSignalSpy ended(panel.session(), &DeviceSession::ended);
    panel.connectTo(dir.filePath(QStringLiteral("ttyNoSuchPort")));
    QTRY_VERIFY_WITH_TIMEOUT(ended.count() == 1, 15000);
    QCOMPARE(ended.at(0).at(0).value<SessionEnd>(), SessionEnd::Failed);
    const QString why = ended.at(0).at(1).toString();
    QVERIFY(!why.isEmpty());
    // The state line says so; the reason is in a visible banner, and in the empty views.
    QCOMPARE(panel.statusText(), QStringLiteral("Not connected"));
    QCOMPARE(panel.errorText(), why);
    auto* banner = panel.findChild<QLabel*>(QStringLiteral("liveError"));
    QVERIFY(banner && banner->isVisible());
    QVERIFY(banner->height() >= banner->fontMetrics().height());
    QVERIFY(panel.views()->notice().startsWith(QStringLiteral("Not connected")));
    QVERIFY(panel.views()->notice().contains(why));
    QVERIFY(!panel.findChild<QPushButton*>(QStringLiteral("liveSave"))->isEnabled());  // nothing to save
}

void TestLivePanel::defaultRecordingNameHasDeviceAndTime()
{
    QCOMPARE(defaultRecordingName(QStringLiteral("037003F1"), QDateTime(QDate(2026, 11, 25), QTime(14, 32, 10))),
             QStringLiteral("MTi-037003F1-2026-11-25-1432.mtb"));
    QCOMPARE(defaultRecordingName(QString(), QDateTime(QDate(2026, 1, 2), QTime(3, 4))), QStringLiteral("MTi-2026-01-02-0304.mtb"));
    LivePanel panel;
    const QFileInfo suggested(panel.suggestedRecordingPath());
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    QCOMPARE(suggested.absolutePath(), QFileInfo(documents.isEmpty() ? QDir::homePath() : documents).absoluteFilePath());
    QVERIFY(suggested.fileName().startsWith(QStringLiteral("MTi-") + QDate::currentDate().toString(QStringLiteral("yyyy-MM-dd"))));
}

void TestLivePanel::unrecordedSessionCanBeSavedAfterDisconnect()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("ttyMTi3"));
    Emulator emulator;
    const QString problem = emulator.start(link, QString(), kFaults + QStringList{QStringLiteral("--once")});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));

    LivePanel panel;
    panel.resize(600, 1200);
    panel.show();
    QSignalSpy identified(panel.session(), &DeviceSession::deviceIdentified);
    QSignalSpy ended(panel.session(), &DeviceSession::ended);
    QSignalSpy finished(&panel, &LivePanel::recordingFinished);
    panel.connectTo(link);
    QTRY_VERIFY_WITH_TIMEOUT(identified.count() == 1, 15000);
    // Once the device is known, its id names the proposed recording.
    const QString deviceId = panel.session()->deviceInfo().deviceIdText();
    QVERIFY(QFileInfo(panel.suggestedRecordingPath()).fileName().startsWith(QStringLiteral("MTi-%1-").arg(deviceId)));
    QTRY_VERIFY_WITH_TIMEOUT(panel.sampleCount() >= 800, 30000);
    QVERIFY(panel.views()->notice().isEmpty());  // the views show data now
    QTRY_VERIFY_WITH_TIMEOUT(panel.findChild<QLabel*>(QStringLiteral("liveDuration"))->text() != QStringLiteral("-"), 5000);
    panel.disconnectDevice();
    QTRY_VERIFY_WITH_TIMEOUT(ended.count() == 1, 15000);
    emulator.stop();

    // The live summary is this session's.
    const Summary& summary = panel.estimator()->result().summary;
    QCOMPARE(panel.findChild<QLabel*>(QStringLiteral("liveSteps"))->text(), QString::number(summary.steps));
    QVERIFY(panel.findChild<QLabel*>(QStringLiteral("liveEndToStart"))->text().endsWith(QStringLiteral(" m")));
    // ... and in a line over the live path, where the user looks while walking.
    QVERIFY2(panel.views()->summaryLine().startsWith(QStringLiteral("Live: %1 steps, ").arg(summary.steps)),
             qPrintable(panel.views()->summaryLine()));
    // Wrapped, not cut at the edge of a narrow view (the 2D tab at 1280x800 cut it after "warnings: n").
    QWidget* path = panel.views()->trajectory2D();
    auto* line = path->findChild<QLabel*>(QStringLiteral("liveSummaryLine"));
    QVERIFY(line);
    for (const int width : {600, 240}) {
        panel.resize(width, 1200);
        QTRY_VERIFY2(path->rect().contains(line->geometry()),
                     qPrintable(QStringLiteral("%1 px view, %2 px line").arg(path->width()).arg(line->geometry().right())));
        QVERIFY(line->height() >= line->heightForWidth(line->width()));
        if (width == 600)  // room for one line: one line, as before
            QVERIFY2(line->height() < 2 * line->fontMetrics().height(), qPrintable(QString::number(line->height())));
    }

    QVERIFY(panel.hasUnsavedSamples());
    QVERIFY(panel.findChild<QPushButton*>(QStringLiteral("liveSave"))->isEnabled());
    const QString csv = dir.filePath(QStringLiteral("kept.csv"));
    QCOMPARE(panel.saveSamplesTo(csv), QString());
    QVERIFY(!panel.hasUnsavedSamples());
    QCOMPARE(finished.count(), 1);  // the workspace opens it
    QCOMPARE(finished.at(0).at(0).toString(), csv);
    const ImportResult saved = importRecording(csv.toStdString());
    QVERIFY2(saved.ok(), saved.ok() ? "" : saved.error->message.c_str());
    const std::vector<LiveSample>& received = panel.receivedSamples();
    QCOMPARE(saved.recording.samples.size(), received.size());
    for (std::size_t k = 0; k < received.size(); ++k) {
        QVERIFY(sameValues(saved.recording.samples[k], received[k].imu));
        QCOMPARE(saved.recording.samples[k].time_s, received[k].imu.time_s);
    }
    // A bad destination says so and keeps the samples.
    QVERIFY(!panel.saveSamplesTo(dir.filePath(QStringLiteral("no/such/folder/x.csv"))).isEmpty());
    QCOMPARE(panel.receivedSamples().size(), received.size());

    // In the workspace, the window's status line is the session's while a live view is in front
    // (it once kept the recorded walk's figures there), and is given back when the user leaves.
    auto* trajectoryTabs = new QTabWidget(&panel);  // the panel's children: they outlive its session
    auto* signalTabs = new QTabWidget(&panel);
    auto* recordedView = new QWidget;
    trajectoryTabs->addTab(recordedView, QStringLiteral("Trajectory 2D"));
    signalTabs->addTab(new QWidget, QStringLiteral("Signals"));  // in front: the live views come after
    QSignalSpy liveStatus(&panel, &LivePanel::liveStatusChanged);
    panel.moveViewsInto(trajectoryTabs, signalTabs);
    trajectoryTabs->setCurrentWidget(panel.views()->trajectory2D());
    QVERIFY(!liveStatus.isEmpty());
    QCOMPARE(liveStatus.last().at(0).toString(), panel.views()->summaryLine());
    QCOMPARE(panel.statusLine(), panel.views()->summaryLine());
    trajectoryTabs->setCurrentWidget(recordedView);
    QCOMPARE(liveStatus.last().at(0).toString(), QString());
}

QTEST_MAIN(TestLivePanel)
#include "tst_livepanel.moc"
