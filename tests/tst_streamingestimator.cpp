// The causal (live) pipeline against the offline one: the same numbers to the last bit once the
// data are complete, and while they arrive, estimates that only use samples already pushed.
#include "TestData.h"
#include "detect/StanceDetector.h"
#include "detect/StatisticDetectors.h"
#include "io/Import.h"
#include "metrics/Evaluation.h"
#include "nav/Alignment.h"
#include "nav/Pipeline.h"
#include "nav/StreamingEstimator.h"
#include "sim/WalkSimulator.h"

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <random>

using namespace footpath;

Q_DECLARE_METATYPE(footpath::Recording)
Q_DECLARE_METATYPE(footpath::Parameters)

namespace {

// Timestamps in the windows are compared with a 1e-9 s tolerance (StanceDetector.cpp); the same
// slack here, twice, for bounds that add two window ends.
constexpr double kTimeSlack_s = 2e-9;

/// Same bits: what "value for value" means (a NaN equals the same NaN, 0.0 differs from -0.0).
bool sameBits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

QString differenceAt(const char* what, std::size_t k, double a, double b)
{
    return QString("%1[%2]: %3 streamed, %4 offline").arg(what).arg(k).arg(a, 0, 'g', 17).arg(b, 0, 'g', 17);
}

QString firstDifference(const char* what, const std::vector<double>& a, const std::vector<double>& b,
                        std::size_t count)
{
    for (std::size_t k = 0; k < count; ++k)
        if (!sameBits(a[k], b[k]))
            return differenceAt(what, k, a[k], b[k]);
    return {};
}

QString firstDifference(const char* what, const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b,
                        std::size_t count)
{
    for (std::size_t k = 0; k < count; ++k)
        for (int i = 0; i < 3; ++i)
            if (!sameBits(a[k][i], b[k][i]))
                return differenceAt(what, k, a[k][i], b[k][i]) + QString(" (component %1)").arg(i);
    return {};
}

QString firstDifference(const char* what, const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                        std::size_t count)
{
    for (std::size_t k = 0; k < count; ++k)
        if (a[k] != b[k])
            return differenceAt(what, k, a[k], b[k]);
    return {};
}

QString firstStepDifference(const std::vector<Step>& a, const std::vector<Step>& b, std::size_t count)
{
    for (std::size_t k = 0; k < count; ++k) {
        const double fieldsA[] = {a[k].stanceStart_s, a[k].stanceEnd_s, a[k].position_m.x(), a[k].position_m.y(),
                                  a[k].position_m.z(), a[k].strideLength_m, a[k].strideDuration_s};
        const double fieldsB[] = {b[k].stanceStart_s, b[k].stanceEnd_s, b[k].position_m.x(), b[k].position_m.y(),
                                  b[k].position_m.z(), b[k].strideLength_m, b[k].strideDuration_s};
        for (std::size_t i = 0; i < std::size(fieldsA); ++i)
            if (!sameBits(fieldsA[i], fieldsB[i]))
                return differenceAt("steps", k, fieldsA[i], fieldsB[i]) + QString(" (field %1)").arg(i);
    }
    return {};
}

/// The first per-sample value or step of the first `samples` samples and `steps` steps that differs;
/// empty if none. Both results must hold at least that many.
QString firstDifferenceInPrefix(const Result& a, const Result& b, std::size_t samples, std::size_t steps)
{
    const QString differences[] = {
        firstDifference("time_s", a.time_s, b.time_s, samples),
        firstDifference("position_m", a.position_m, b.position_m, samples),
        firstDifference("velocity_mps", a.velocity_mps, b.velocity_mps, samples),
        firstDifference("rollPitchYaw_rad", a.rollPitchYaw_rad, b.rollPitchYaw_rad, samples),
        firstDifference("gyroBias_radps", a.gyroBias_radps, b.gyroBias_radps, samples),
        firstDifference("accBias_mps2", a.accBias_mps2, b.accBias_mps2, samples),
        firstDifference("c1", a.flags.c1, b.flags.c1, samples),
        firstDifference("c2", a.flags.c2, b.flags.c2, samples),
        firstDifference("c3", a.flags.c3, b.flags.c3, samples),
        firstDifference("c", a.flags.c, b.flags.c, samples),
        firstDifference("stance", a.flags.stance, b.flags.stance, samples),
        firstStepDifference(a.steps, b.steps, steps),
    };
    for (const QString& difference : differences)
        if (!difference.isEmpty())
            return difference;
    return {};
}

QString summaryDifference(const Summary& a, const Summary& b)
{
    if (a.samples != b.samples || a.stancePhases != b.stancePhases || a.steps != b.steps)
        return QString("counts: %1/%2/%3 streamed, %4/%5/%6 offline")
            .arg(a.samples).arg(a.stancePhases).arg(a.steps).arg(b.samples).arg(b.stancePhases).arg(b.steps);
    const double fieldsA[] = {a.duration_s, a.pathLength_m, a.endToStart_m, a.endToStartPct};
    const double fieldsB[] = {b.duration_s, b.pathLength_m, b.endToStart_m, b.endToStartPct};
    for (std::size_t i = 0; i < std::size(fieldsA); ++i)
        if (!sameBits(fieldsA[i], fieldsB[i]))
            return differenceAt("summary", i, fieldsA[i], fieldsB[i]);
    return {};
}

/// Every per-sample value, step and summary field (runtime_s aside) bitwise equal, after the sizes.
void compareWholeResults(const Result& streamed, const Result& offline)
{
    const std::size_t n = offline.time_s.size();
    for (std::size_t size : {streamed.time_s.size(), streamed.position_m.size(), streamed.velocity_mps.size(),
                             streamed.rollPitchYaw_rad.size(), streamed.gyroBias_radps.size(),
                             streamed.accBias_mps2.size(), streamed.flags.c1.size(), streamed.flags.c2.size(),
                             streamed.flags.c3.size(), streamed.flags.c.size(), streamed.flags.stance.size()})
        QCOMPARE(size, n);
    QCOMPARE(offline.flags.stance.size(), n);
    QCOMPARE(streamed.steps.size(), offline.steps.size());
    QCOMPARE(firstDifferenceInPrefix(streamed, offline, n, offline.steps.size()), QString());
    QCOMPARE(summaryDifference(streamed.summary, offline.summary), QString());
    QCOMPARE(streamed.summary.runtime_s, 0.0);
    QCOMPARE(streamed.cancelled, false);
}

/// The offline pipeline with the filter alone: the live estimate is causal, so it equals the
/// offline filter, not the smoother (whose backward pass needs the whole recording).
Result runOffline(const Recording& recording, Parameters params)
{
    if (params.estimatorKind() == EstimatorKind::Smoother)
        params.estimator = static_cast<int>(EstimatorKind::Ekf);
    PipelineOutput output = runPipeline(recording, params);
    if (!output.error.empty())
        qFatal("%s", output.error.c_str());
    return std::move(output.result);
}

Result runStreaming(const std::vector<ImuSample>& samples, const Parameters& params)
{
    StreamingEstimator estimator(params);
    for (const ImuSample& sample : samples)
        estimator.push(sample);
    estimator.finish();
    if (!estimator.error().empty())
        qFatal("%s", estimator.error().c_str());
    if (estimator.rejectedSamples() != 0 || estimator.pendingSamples() != 0)
        qFatal("%zu samples rejected, %zu left pending", estimator.rejectedSamples(), estimator.pendingSamples());
    return estimator.result();
}

/// Noise and biases a few times an MTi's, so that tight thresholds make the flags flicker.
WalkSimulatorConfig noisySensor(double rate_hz, std::uint32_t seed = 1)
{
    WalkSimulatorConfig config;
    config.rate_hz = rate_hz;
    config.seed = seed;
    config.accNoiseStd_mps2 = 0.04;
    config.gyrNoiseStd_radps = 0.005;
    config.accBias_mps2 = Eigen::Vector3d(0.02, -0.03, 0.04);
    config.gyrBias_radps = Eigen::Vector3d(0.004, -0.003, 0.005);
    return config;
}

Recording simulatedRectangle(double rate_hz, std::uint32_t seed = 1)
{
    return simulateWalk(closedRectanglePath(12.0, 8.0), noisySensor(rate_hz, seed)).recording;
}

/// Each time moved by up to maxJitter_s either way: windows then hold even counts too (median ties).
Recording withJitteredClock(Recording recording, double maxJitter_s)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-maxJitter_s, maxJitter_s);
    for (ImuSample& sample : recording.samples)
        sample.time_s += jitter(random);
    return recording;
}

/// Thresholds near the simulated noise: C2 and C3 flicker during stance and the median has work.
Parameters flickeringDetector()
{
    Parameters params;
    params.acc_std_max_mps2 = 0.045;
    params.gyr_max_radps = 0.012;
    return params;
}

/// Removes the samples with from_s < t < to_s: a stretch of lost packets.
Recording withGap(Recording recording, double from_s, double to_s)
{
    std::vector<ImuSample>& samples = recording.samples;
    samples.erase(std::remove_if(samples.begin(), samples.end(),
                                 [&](const ImuSample& s) { return s.time_s > from_s && s.time_s < to_s; }),
                  samples.end());
    return recording;
}

Recording readRecording(const QString& relativePath, const ImportOptions& options = {})
{
    ImportResult read = importRecording(datasetPath(relativePath).toStdString(), options);
    if (!read.ok())
        qFatal("%s", read.error->text().c_str());
    return std::move(read.recording);
}

/// The paper's C1/C2/C3 detector with other windows.
Parameters withDetector(double windowHalf_s, double medianWindow_s)
{
    Parameters params = guo2015Parameters();
    params.window_half_s = windowHalf_s;
    params.median_window_s = medianWindow_s;
    return params;
}


/// The recording from the middle of its `swing`-th swing (true stance runs of 0 after the still
/// start, counted from 1) on: a recording started mid-walk. Returns the index cut at.
std::size_t cutMidSwing(const SimulatedWalk& walk, int swing, Recording& cut)
{
    const std::vector<std::uint8_t>& stance = walk.trueStance;
    int seen = 0;
    for (std::size_t k = 1; k < stance.size(); ++k) {
        if (!(stance[k - 1] && !stance[k]) || ++seen < swing)
            continue;
        std::size_t end = k;
        while (end < stance.size() && !stance[end])
            ++end;
        const std::size_t middle = (k + end) / 2;
        cut.samples.assign(walk.recording.samples.begin() + static_cast<std::ptrdiff_t>(middle),
                           walk.recording.samples.end());
        return middle;
    }
    qFatal("the walk has fewer than %d swings", swing);
}

/// The largest distance of a stance position from the truth, both relative to the start (result
/// sample `start`, which is walk sample cutAt + start).
double worstStanceError(const Result& result, const SimulatedWalk& walk, std::size_t cutAt, std::size_t start)
{
    const Eigen::Vector3d origin = walk.truePosition_m[cutAt + start];
    double worst_m = 0.0;
    for (const Step& step : result.steps) {
        const auto k = static_cast<std::size_t>(
            std::lower_bound(result.time_s.begin(), result.time_s.end(), step.stanceStart_s) - result.time_s.begin());
        worst_m = std::max(worst_m, (step.position_m - result.position_m[start] - (walk.truePosition_m[cutAt + k] - origin)).norm());
    }
    return worst_m;
}

const PlausibilityWarning* findWarning(const Result& result, PlausibilityWarning::Kind kind)
{
    const auto found = std::find_if(result.warnings.begin(), result.warnings.end(),
                                    [kind](const PlausibilityWarning& w) { return w.kind == kind; });
    return found == result.warnings.end() ? nullptr : &*found;
}

/// A result of a recording that starts mid-walk: the filter started at the first stance, every
/// sample before it holds the start state, and the warning says so over exactly that span.
std::size_t checkHeldUntilFirstStance(const Result& result)
{
    const std::size_t start = alignmentStart(result.flags.stance);
    [&] {
        QVERIFY2(start > 0, "the cut recording starts in a stance");
        QVERIFY(result.flags.stance[start] && !result.flags.stance[start - 1]);
        for (std::size_t k = 0; k < start; ++k) {
            QVERIFY2(result.position_m[k] == Eigen::Vector3d::Zero(), qPrintable(QString("held sample %1 moved").arg(k)));
            QVERIFY(result.velocity_mps[k] == Eigen::Vector3d::Zero());
            // Equal up to rounding: the first filtered sample's attitude went through a (zero) correction.
            QVERIFY((result.rollPitchYaw_rad[k] - result.rollPitchYaw_rad[start]).cwiseAbs().maxCoeff() < 1e-12);
        }
        const PlausibilityWarning* warning = findWarning(result, PlausibilityWarning::Kind::NoInitialRest);
        QVERIFY2(warning, "no warning about the mid-walk start");
        QCOMPARE(warning->start_s, result.time_s.front());
        QCOMPARE(warning->end_s, result.time_s[start]);
        QVERIFY2(warning->message.find("mid-walk") != std::string::npos, warning->message.c_str());
    }();
    return start;
}
}  // namespace

class TestStreamingEstimator : public QObject {
    Q_OBJECT
private slots:
    void equalsRunPipelineOnSimulatedWalks_data()
    {
        QTest::addColumn<Recording>("recording");
        QTest::addColumn<Parameters>("params");
        Parameters zuptOnly;
        zuptOnly.use_zaru = false;
        Parameters zaruOnly;
        zaruOnly.use_zupt = false;
        Parameters noUpdates;
        noUpdates.use_zupt = false;
        noUpdates.use_zaru = false;
        Parameters longAlignment;  // beyond the 2 s still start: moving samples take part
        longAlignment.alignment_s = 2.7;
        Parameters shortAlignment;
        shortAlignment.alignment_s = 0.05;
        Parameters tightDetector = withDetector(0.05, 0.03);
        tightDetector.acc_std_max_mps2 = 0.2;
        Parameters wideDetector = withDetector(0.2, 0.25);
        wideDetector.acc_std_max_mps2 = 1.5;
        const Recording at100 = simulatedRectangle(100.0);
        const Recording at200 = simulatedRectangle(200.0, 2);
        QTest::newRow("100 Hz, defaults") << at100 << Parameters();
        QTest::newRow("200 Hz, defaults") << at200 << Parameters();
        QTest::newRow("100 Hz, wide windows") << at100 << wideDetector;
        QTest::newRow("100 Hz, windows off the sample grid") << at100 << withDetector(0.1537, 0.1189);
        QTest::newRow("200 Hz, windows off the sample grid") << at200 << withDetector(0.0123, 0.2571);
        QTest::newRow("100 Hz, tight detector") << at100 << tightDetector;
        const Recording jittered = withJitteredClock(at100, 0.003);
        QTest::newRow("100 Hz jittered clock, defaults") << jittered << Parameters();
        QTest::newRow("100 Hz jittered clock, flickering detector") << jittered << flickeringDetector();
        QTest::newRow("100 Hz, ZUPT only") << at100 << zuptOnly;
        QTest::newRow("200 Hz, ZARU only") << at200 << zaruOnly;
        QTest::newRow("100 Hz, no updates") << at100 << noUpdates;
        QTest::newRow("100 Hz, long alignment") << at100 << longAlignment;
        QTest::newRow("200 Hz, short alignment") << at200 << shortAlignment;
        WalkSimulatorConfig withMagnetometer = noisySensor(100.0, 3);
        withMagnetometer.withMagnetometer = true;
        QTest::newRow("100 Hz stairs, magnetometer")
            << simulateWalk(stairsPath(6, 0.17, 0.6), withMagnetometer).recording << Parameters();
        WalkSimulatorConfig movingAtOnce = noisySensor(100.0, 4);
        movingAtOnce.initialStill_s = 0.0;
        movingAtOnce.finalStill_s = 0.0;  // ends in a swing: the open phase and truncated windows
        QTest::newRow("100 Hz, no still start or end")
            << simulateWalk(straightLinePath(8.0), movingAtOnce).recording << Parameters();
        // Every measurement source is causal: live gives the offline numbers with all of them on.
        Parameters everySource;
        everySource.filter_states = static_cast<int>(FilterStates::Fifteen);
        everySource.use_zaru = everySource.use_hdr = everySource.use_iper = everySource.use_zuna = true;
        everySource.use_baro = everySource.use_mag_heading = true;
        WalkSimulatorConfig withMagnetometerAndPressure = noisySensor(100.0, 5);
        withMagnetometerAndPressure.withMagnetometer = withMagnetometerAndPressure.withPressure = true;
        QTest::newRow("100 Hz rectangle, every measurement source")
            << simulateWalk(closedRectanglePath(12.0, 8.0), withMagnetometerAndPressure).recording << everySource;
    }

    void felizLiveRunsTheFilterAndSaysSo()
    {
        Parameters feliz;
        feliz.estimator = static_cast<int>(EstimatorKind::Feliz);
        const Recording recording = simulatedRectangle(100.0);
        const Result live = runStreaming(recording.samples, feliz);
        QVERIFY(live.steps.size() > 3);
        const auto note = std::find_if(live.methodNotes.begin(), live.methodNotes.end(),
                                       [](const MethodNote& n) { return n.method == "feliz"; });
        QVERIFY(note != live.methodNotes.end());
        QVERIFY(note->message.find("Kalman filter") != std::string::npos);
    }

    void equalsRunPipelineOnSimulatedWalks()
    {
        QFETCH(Recording, recording);
        QFETCH(Parameters, params);
        const Result offline = runOffline(recording, params);
        QVERIFY2(offline.steps.size() > 3, qPrintable(QString("%1 steps").arg(offline.steps.size())));
        compareWholeResults(runStreaming(recording.samples, params), offline);
    }

    // A recording that starts mid-swing: the filter waits for the first stance, aligns on it, and
    // the path from there on follows the truth as a walk started at rest does.
    void midWalkStartAlignsAtTheFirstStance()
    {
        const SimulatedWalk walk = simulateWalk(closedRectanglePath(12.0, 8.0), noisySensor(100.0, 6));
        Recording cut;
        const std::size_t cutAt = cutMidSwing(walk, 3, cut);  // still on the first side, along +x
        const Result result = runOffline(cut, Parameters());
        const std::size_t start = checkHeldUntilFirstStance(result);
        QVERIFY2(result.time_s[start] - result.time_s.front() < 0.5,
                 qPrintable(QString("first stance found %1 s after the cut").arg(result.time_s[start] - result.time_s.front())));
        // Level at the first stance (the simulated foot rests flat), not tilted by the swing.
        QVERIFY(std::abs(result.rollPitchYaw_rad[start].x()) < 0.02 && std::abs(result.rollPitchYaw_rad[start].y()) < 0.02);
        // Every later stance as near the truth (relative to the first one) as when the same walk
        // is recorded from its still start.
        const double cutError_m = worstStanceError(result, walk, cutAt, start);
        const double wholeError_m = worstStanceError(runOffline(walk.recording, Parameters()), walk, 0, 0);
        QVERIFY2(result.steps.size() > 20, qPrintable(QString("%1 stance phases").arg(result.steps.size())));
        QVERIFY2(cutError_m < 1.5 * wholeError_m + 0.1,
                 qPrintable(QString("a stance %1 m off the truth, %2 m from a still start").arg(cutError_m).arg(wholeError_m)));
        // Live does the same, value for value.
        compareWholeResults(runStreaming(cut.samples, Parameters()), result);
    }

    // A real walk cut to start mid-walk (the file written again from a swing on): the path from the
    // first stance on is as close to the reference as the whole file's.
    void midWalkStartOfARealRecording()
    {
        FOOTPATH_REQUIRE_DATASETS();
        const QString file = datasetPath("pyshoe-vicon/2017-11-22-11-22-03.csv");
        const Recording whole = readRecording("pyshoe-vicon/2017-11-22-11-22-03.csv");
        const Result wholeResult = runOffline(whole, Parameters());
        QVERIFY(findWarning(wholeResult, PlausibilityWarning::Kind::NoInitialRest) == nullptr);
        // The middle of the fifth real swing (0.3 s or longer, not a flicker of the detector).
        const std::vector<std::uint8_t>& stance = wholeResult.flags.stance;
        std::size_t cutAt = 0;
        for (std::size_t k = 1, seen = 0; k < stance.size() && cutAt == 0; ++k) {
            if (!stance[k - 1] || stance[k])
                continue;
            std::size_t end = k;
            while (end < stance.size() && !stance[end])
                ++end;
            if (wholeResult.time_s[end - 1] - wholeResult.time_s[k] >= 0.3 && ++seen == 5)
                cutAt = (k + end) / 2;
        }
        QVERIFY(cutAt > 0);

        QFile in(file);
        QVERIFY(in.open(QIODevice::ReadOnly));
        QList<QByteArray> lines = in.readAll().split('\n');
        QTemporaryDir dir;
        const QString cutPath = dir.filePath("midwalk.csv");
        QFile out(cutPath);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(lines.front() + '\n');  // the header, then the rows from the cut on
        for (int line = int(cutAt) + 1; line < lines.size(); ++line)
            out.write(lines[line] + '\n');
        out.close();
        ImportResult read = importRecording(cutPath.toStdString());
        QVERIFY(read.ok());
        QCOMPARE(read.recording.samples.size(), whole.samples.size() - cutAt);
        QCOMPARE(read.recording.samples.front().acc_mps2, whole.samples[cutAt].acc_mps2);

        const Result result = runOffline(read.recording, Parameters());
        const std::size_t start = checkHeldUntilFirstStance(result);
        QVERIFY(result.time_s[start] - result.time_s.front() < 1.0);
        const auto tail = [](const std::vector<Eigen::Vector3d>& v, std::size_t from) {
            return std::vector<Eigen::Vector3d>(v.begin() + static_cast<std::ptrdiff_t>(from), v.end());
        };
        const ArmseResult cutError = computeArmse(tail(result.position_m, start),
                                                  tail(read.recording.reference.positions_m, start));
        const ArmseResult wholeError = computeArmse(wholeResult.position_m, whole.reference.positions_m);
        QVERIFY2(cutError.armse2d_m < std::max(2.0 * wholeError.armse2d_m, wholeError.armse2d_m + 0.3),
                 qPrintable(QString("ARMSE 2D %1 m cut mid-walk, %2 m whole").arg(cutError.armse2d_m).arg(wholeError.armse2d_m)));
        compareWholeResults(runStreaming(read.recording.samples, Parameters()), result);
    }

    void equalsRunPipelineOnRealRecordings_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QStringList>("columnMap");
        QTest::addColumn<int>("minimumSteps");  // so that the comparison covers steps at all
        QTest::newRow("pyshoe-vicon walk") << "pyshoe-vicon/2017-11-22-11-22-03.csv" << QStringList() << 10;
        // The default detector finds few stances in a fast trial; the filter runs through it anyway.
        QTest::newRow("pyshoe-vicon fast trial") << "pyshoe-vicon/2017-11-27-11-11-24.csv" << QStringList() << 1;
        // ecg-xmu files have no header; this one holds time [ms], acc and gyro.
        QTest::newRow("ecg-xmu rectangle_72m")
            << "ecg-xmu/rectangle_72m.TXT"
            << QStringList{"time_ms", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"} << 10;
    }

    void equalsRunPipelineOnRealRecordings()
    {
        FOOTPATH_REQUIRE_DATASETS();
        QFETCH(QString, file);
        QFETCH(QStringList, columnMap);
        QFETCH(int, minimumSteps);
        ImportOptions options;
        for (const QString& role : columnMap)
            options.columnMap.push_back(role.toStdString());
        const Recording recording = readRecording(file, options);
        const Result offline = runOffline(recording, Parameters());
        QVERIFY2(offline.steps.size() >= static_cast<std::size_t>(minimumSteps),
                 qPrintable(QString("%1 steps").arg(offline.steps.size())));
        compareWholeResults(runStreaming(recording.samples, Parameters()), offline);
    }

    void estimatesTrailTheNewestSampleByTheLatency_data()
    {
        QTest::addColumn<double>("rate_hz");
        QTest::addColumn<std::size_t>("lookAheadSamples");
        // Sample k is final when the C2 window (0.15 s) of the last sample in its median window
        // (0.055 s) has a sample beyond it: at 100 Hz, k + 5 + 15 + 1; at 200 Hz, k + 11 + 30 + 1.
        QTest::newRow("100 Hz") << 100.0 << std::size_t(21);
        QTest::newRow("200 Hz") << 200.0 << std::size_t(42);
    }

    void estimatesTrailTheNewestSampleByTheLatency()
    {
        QFETCH(double, rate_hz);
        QFETCH(std::size_t, lookAheadSamples);
        const Parameters params = guo2015Parameters();
        const double latency = StreamingEstimator::latency_s(params);
        const std::vector<ImuSample> samples = simulatedRectangle(rate_hz).samples;
        const double alignmentEnd = samples.front().time_s + params.alignment_s;
        const auto alignmentSamples = static_cast<std::size_t>(std::count_if(
            samples.begin(), samples.end(), [&](const ImuSample& s) { return s.time_s <= alignmentEnd; }));
        StreamingEstimator estimator(params);
        for (std::size_t received = 1; received <= samples.size(); ++received) {
            estimator.push(samples[received - 1]);
            const double newest = samples[received - 1].time_s;
            const std::vector<double>& estimated = estimator.result().time_s;
            QCOMPARE(estimator.pendingSamples(), received - estimated.size());
            // Alignment waits for the flags of the whole alignment period, then runs at once.
            QCOMPARE(estimator.aligned(), received >= alignmentSamples + lookAheadSamples);
            if (estimator.aligned())
                QCOMPARE(estimator.pendingSamples(), lookAheadSamples);
            if (!estimated.empty())
                QVERIFY2(estimated.back() <= newest - latency + kTimeSlack_s,
                         qPrintable(QString("sample at %1 s estimated at %2 s").arg(estimated.back()).arg(newest)));
        }
        QCOMPARE(estimator.result().summary.samples, samples.size() - lookAheadSamples);
        estimator.finish();
        QCOMPARE(estimator.pendingSamples(), std::size_t(0));
        QCOMPARE(estimator.result().time_s.size(), samples.size());
    }

    void estimatesNeverChangeOnceProduced()
    {
        const std::vector<ImuSample> samples = simulatedRectangle(100.0).samples;
        StreamingEstimator estimator{Parameters()};
        std::vector<Result> snapshots;
        for (std::size_t k = 0; k < samples.size(); ++k) {
            estimator.push(samples[k]);
            if (k % 701 == 350)
                snapshots.push_back(estimator.result());
        }
        estimator.finish();
        const Result& final = estimator.result();
        QVERIFY(snapshots.size() > 4);
        for (const Result& snapshot : snapshots) {
            QCOMPARE(snapshot.flags.stance.size(), snapshot.time_s.size());
            QVERIFY(snapshot.steps.size() <= final.steps.size());
            QCOMPARE(firstDifferenceInPrefix(snapshot, final, snapshot.time_s.size(), snapshot.steps.size()),
                     QString());
        }
        QVERIFY(!snapshots.back().steps.empty());  // steps appear while walking, not only at the end
    }

    void summaryIsKeptUpWhileWalking()
    {
        const std::vector<ImuSample> samples = simulatedRectangle(100.0).samples;
        StreamingEstimator estimator{Parameters()};
        for (std::size_t k = 0; k < samples.size(); ++k) {
            estimator.push(samples[k]);
            const Result& result = estimator.result();
            if (result.time_s.empty() || k % 97 != 0)
                continue;
            QCOMPARE(result.summary.samples, result.time_s.size());
            QVERIFY(sameBits(result.summary.duration_s, result.time_s.back() - result.time_s.front()));
            QCOMPARE(result.summary.stancePhases, result.steps.size());
            QVERIFY(sameBits(result.summary.pathLength_m, stancePathLength(result.steps)));
            const LoopClosure closure = computeLoopClosure(result.position_m, result.summary.pathLength_m);
            QVERIFY(sameBits(result.summary.endToStart_m, closure.dbse_m));
        }
    }

    // A flag handed out while walking is final: detectStance on just the samples received so far
    // gives it too, although its windows there are truncated at the newest sample.
    void flagsEqualDetectStanceOnTheSamplesSoFar()
    {
        const std::vector<ImuSample> all = withJitteredClock(simulatedRectangle(100.0), 0.003).samples;
        const Parameters params = flickeringDetector();
        StreamingEstimator estimator(params);
        std::vector<ImuSample> received;
        for (std::size_t k = 0; k < all.size(); ++k) {
            estimator.push(all[k]);
            received.push_back(all[k]);
            if (k % 53 != 0)
                continue;
            const StanceFlags prefix = detectStance(received, params);
            const Result& result = estimator.result();
            const std::size_t n = result.time_s.size();
            QCOMPARE(firstDifference("c1", result.flags.c1, prefix.c1, n), QString());
            QCOMPARE(firstDifference("c2", result.flags.c2, prefix.c2, n), QString());
            QCOMPARE(firstDifference("c3", result.flags.c3, prefix.c3, n), QString());
            QCOMPARE(firstDifference("c", result.flags.c, prefix.c, n), QString());
            QCOMPARE(firstDifference("stance", result.flags.stance, prefix.stance, n), QString());
        }
    }

    void statisticDetectorKeepsOnlyTheOpenWindows()
    {
        const Parameters params;  // the adaptive SHOE detector
        const std::vector<ImuSample> samples = simulatedRectangle(100.0).samples;
        StatisticStanceDetector detector(params);
        std::deque<SampleStanceFlags> decided;
        // The statistic window and the threshold's half window reach back from the newest sample;
        // the dead samples and scores before them are erased in batches.
        const double reach_s = params.zv_window_s + params.zv_adapt_window_s / 2.0;
        const auto open = static_cast<std::size_t>(std::ceil(reach_s * 100.0)) + 3;
        const std::size_t bound = 2 * open + 2 * SlidingBuffer<ImuSample>::kMinimumDrop;
        const double latency_s = StatisticStanceDetector::latency_s(params);
        const auto latency = static_cast<std::size_t>(std::ceil(latency_s * 100.0)) + 3;
        std::size_t pushed = 0;
        for (const ImuSample& sample : samples) {
            detector.push(sample, decided);
            ++pushed;
            QVERIFY(detector.bufferedSamples() <= bound);
            QVERIFY(pushed - decided.size() <= latency);
        }
        detector.finish(decided);
        QCOMPARE(decided.size(), samples.size());
        const StanceFlags offline = detectStance(samples, params);
        for (std::size_t k = 0; k < samples.size(); ++k)
            QVERIFY(decided[k].stance == offline.stance[k] && decided[k].logStatistic == offline.logStatistic[k]);
    }

    void causalDetectorKeepsOnlyTheOpenWindows()
    {
        const Parameters params = guo2015Parameters();
        const std::vector<ImuSample> samples = simulatedRectangle(100.0).samples;
        CausalStanceDetector detector(params);
        std::deque<SampleStanceFlags> decided;
        // The open windows reach back 2 window_half_s (C2) or window_half_s + median_window_s
        // (median) from the newest sample; the dead samples before them are dropped in batches.
        const auto open = static_cast<std::size_t>(
            std::ceil((2.0 * params.window_half_s + params.median_window_s) * 100.0)) + 3;
        const std::size_t bound = std::max(2 * open, open + CausalStanceDetector::kMinimumDrop);
        for (const ImuSample& sample : samples) {
            detector.push(sample, decided);
            QVERIFY(detector.bufferedSamples() <= bound);
            QCOMPARE(detector.decidedSamples(), decided.size());
        }
        detector.finish(decided);
        QCOMPARE(decided.size(), samples.size());
        const StanceFlags offline = detectStance(samples, params);
        for (std::size_t k = 0; k < samples.size(); ++k)
            QCOMPARE(decided[k].stance, offline.stance[k]);
    }

    void gapsInTimeGiveTheOfflineResult_data()
    {
        QTest::addColumn<double>("from_s");
        QTest::addColumn<double>("to_s");
        QTest::newRow("lost packets during alignment") << 0.304 << 0.6;
        QTest::newRow("0.1 s in a stance") << 2.004 << 2.104;
        QTest::newRow("0.25 s in a swing") << 7.004 << 7.254;
        QTest::newRow("3 s") << 10.004 << 13.004;
    }

    void gapsInTimeGiveTheOfflineResult()
    {
        QFETCH(double, from_s);
        QFETCH(double, to_s);
        const Recording recording = withGap(simulatedRectangle(100.0), from_s, to_s);
        compareWholeResults(runStreaming(recording.samples, Parameters()), runOffline(recording, Parameters()));
    }

    void sampleAfterALongGapClosesEveryWindowBeforeIt()
    {
        const Recording recording = withGap(simulatedRectangle(100.0), 10.004, 13.004);
        StreamingEstimator estimator{guo2015Parameters()};
        std::size_t k = 0;
        while (recording.samples[k].time_s < 13.0)
            estimator.push(recording.samples[k++]);
        QVERIFY(estimator.pendingSamples() > 10);
        estimator.push(recording.samples[k]);
        QCOMPARE(estimator.pendingSamples(), std::size_t(1));
    }

    void samplesNotLaterThanThePreviousAreRejected()
    {
        const std::vector<ImuSample> samples = simulatedRectangle(100.0).samples;
        StreamingEstimator estimator{Parameters()};
        for (std::size_t k = 0; k < samples.size(); ++k) {
            estimator.push(samples[k]);
            if (k == 150)
                estimator.push(samples[k]);  // the same time again
            if (k == 400)
                estimator.push(samples[k - 3]);  // back in time
            if (k == 900) {
                ImuSample noTime = samples[k];
                noTime.time_s = std::numeric_limits<double>::quiet_NaN();
                estimator.push(noTime);
            }
        }
        QCOMPARE(estimator.rejectedSamples(), std::size_t(3));
        estimator.finish();
        estimator.push(samples.back());
        QCOMPARE(estimator.rejectedSamples(), std::size_t(4));
        QVERIFY(estimator.error().empty());
        Recording clean;
        clean.samples = samples;
        compareWholeResults(estimator.result(), runOffline(clean, Parameters()));
    }

    void invalidParametersEstimateNothing()
    {
        Parameters params;
        params.acc_min_mps2 = 12.0;  // above acc_max_mps2
        params.window_half_s = -1.0;
        StreamingEstimator estimator(params);
        QVERIFY(!estimator.error().empty());
        QVERIFY(QString::fromStdString(estimator.error()).contains("acc_min_mps2"));
        QVERIFY(QString::fromStdString(estimator.error()).contains("window_half_s"));
        for (const ImuSample& sample : simulatedRectangle(100.0).samples)
            estimator.push(sample);
        estimator.finish();
        QCOMPARE(estimator.pendingSamples(), std::size_t(0));
        QCOMPARE(estimator.rejectedSamples(), std::size_t(0));
        QVERIFY(!estimator.aligned());
        QVERIFY(estimator.result().time_s.empty());
        QVERIFY(estimator.result().flags.stance.empty());
        QCOMPARE(estimator.parameters().acc_min_mps2, 12.0);
    }

    void finishWithFewerThanTwoSamplesEstimatesNothing()
    {
        StreamingEstimator estimator{Parameters()};
        estimator.push(simulatedRectangle(100.0).samples.front());
        estimator.finish();
        QVERIFY(!estimator.error().empty());
        QVERIFY(estimator.result().time_s.empty());
        Recording one;
        one.samples = {simulatedRectangle(100.0).samples.front()};
        QVERIFY(!runPipeline(one, Parameters()).error.empty());
    }

    void latencyIsTheLookAheadOfBothWindows()
    {
        QCOMPARE(StreamingEstimator::latency_s(withDetector(0.15, 0.11)), 0.15 + 0.055);
        QCOMPARE(StreamingEstimator::latency_s(withDetector(0.4, 0.3)), 0.4 + 0.15);
    }
};

QTEST_APPLESS_MAIN(TestStreamingEstimator)
#include "tst_streamingestimator.moc"
