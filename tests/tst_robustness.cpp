// Numerical robustness on simulated walks: damaged samples (NaN, Inf, time going back), a clipped
// sensor, a foot that never moves, a walk without initial rest, and sampling rates far from
// 100 Hz. Each either gives finite results or a clear message; never a crash or silent NaN.
#include "io/Import.h"
#include "nav/InputCheck.h"
#include "nav/Pipeline.h"
#include "nav/StreamingEstimator.h"
#include "sim/WalkSimulator.h"

#include <QtTest>

#include <limits>
#include <sstream>

using namespace footpath;

namespace {

Recording simulatedWalk(double rate_hz = 100.0)
{
    return simulateWalk(straightLinePath(20.0), mtiClassSensor(rate_hz, 3)).recording;
}

bool allFinite(const Result& result)
{
    for (std::size_t k = 0; k < result.position_m.size(); ++k)
        if (!result.position_m[k].allFinite() || !result.velocity_mps[k].allFinite()
            || !result.rollPitchYaw_rad[k].allFinite())
            return false;
    return std::isfinite(result.summary.pathLength_m);
}

bool anyWarningContains(const std::vector<PlausibilityWarning>& warnings, const QString& text)
{
    return std::any_of(warnings.begin(), warnings.end(), [&text](const PlausibilityWarning& warning) {
        return QString::fromStdString(warning.message).contains(text);
    });
}

/// The recording clipped at +-range_g on every accelerometer axis and +-range_radps on every gyro axis.
Recording clipped(Recording recording, double range_g, double range_radps)
{
    for (ImuSample& sample : recording.samples) {
        sample.acc_mps2 = sample.acc_mps2.cwiseMax(-range_g * 9.81).cwiseMin(range_g * 9.81);
        sample.gyr_radps = sample.gyr_radps.cwiseMax(-range_radps).cwiseMin(range_radps);
    }
    return recording;
}

std::string asCsv(const Recording& recording)
{
    std::ostringstream csv;
    csv.precision(17);
    csv << "time_s,acc_x_mps2,acc_y_mps2,acc_z_mps2,gyr_x_radps,gyr_y_radps,gyr_z_radps\n";
    for (const ImuSample& s : recording.samples)
        csv << s.time_s << ',' << s.acc_mps2.x() << ',' << s.acc_mps2.y() << ',' << s.acc_mps2.z() << ','
            << s.gyr_radps.x() << ',' << s.gyr_radps.y() << ',' << s.gyr_radps.z() << '\n';
    return csv.str();
}

}  // namespace

class TestRobustness : public QObject {
    Q_OBJECT

private slots:
    void damagedSample_pipelineRefusesWithTheSample_data();
    void damagedSample_pipelineRefusesWithTheSample();
    void damagedSample_liveEstimatorSkipsItAndStaysFinite();
    void saturatedSensor_importWarnsPerAxisAndResultIsFinite();
    void noiseFreeStillSensor_isNotSaturated();
    void neverMoving_warnsThatTheSensorHardlyMoved();
    void noInitialRest_warnsAndStaysFinite();
    void extremeRates_giveTheWalksLength_data();
    void extremeRates_giveTheWalksLength();
};

void TestRobustness::damagedSample_pipelineRefusesWithTheSample_data()
{
    QTest::addColumn<int>("field");  // 0 acc x, 1 gyr z, 2 time, 3 time going back
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("expected");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    QTest::newRow("NaN acceleration") << 0 << nan << "sample 501 (t = 5 s) has a non-finite accelerometer value";
    QTest::newRow("Inf rate of turn") << 1 << inf << "sample 501 (t = 5 s) has a non-finite gyroscope value";
    QTest::newRow("-Inf rate of turn") << 1 << -inf << "non-finite gyroscope value";
    QTest::newRow("NaN time") << 2 << nan << "sample 501 has no finite time (nan)";
    QTest::newRow("time going back") << 3 << 1.0 << "sample 501 (t = 1 s) goes back in time from 4.99 s";
}

void TestRobustness::damagedSample_pipelineRefusesWithTheSample()
{
    QFETCH(int, field);
    QFETCH(double, value);
    QFETCH(QString, expected);
    Recording recording = simulatedWalk();
    QCOMPARE(recording.samples[500].time_s, 5.0);
    ImuSample& damaged = recording.samples[500];
    if (field == 0)
        damaged.acc_mps2.x() = value;
    else if (field == 1)
        damaged.gyr_radps.z() = value;
    else
        damaged.time_s = value;
    recording.samples[900].acc_mps2.y() = std::numeric_limits<double>::quiet_NaN();

    const PipelineOutput output = runPipeline(recording, Parameters());
    const QString error = QString::fromStdString(output.error);
    QVERIFY2(error.contains(expected), qPrintable(error));
    QVERIFY2(error.contains("(and 1 more such samples)"), qPrintable(error));
    QVERIFY(output.result.position_m.empty());
}

void TestRobustness::damagedSample_liveEstimatorSkipsItAndStaysFinite()
{
    Recording recording = simulatedWalk();
    recording.samples[500].acc_mps2.x() = std::numeric_limits<double>::quiet_NaN();
    recording.samples[700].gyr_radps.y() = std::numeric_limits<double>::infinity();
    StreamingEstimator estimator{Parameters()};
    for (const ImuSample& sample : recording.samples)
        estimator.push(sample);
    estimator.finish();
    QVERIFY2(estimator.error().empty(), estimator.error().c_str());
    QCOMPARE(estimator.rejectedSamples(), std::size_t(2));
    QCOMPARE(estimator.result().position_m.size(), recording.samples.size() - 2);
    QVERIFY(allFinite(estimator.result()));
    QVERIFY2(std::abs(estimator.result().summary.pathLength_m - 20.0) < 1.0,
             qPrintable(QString::number(estimator.result().summary.pathLength_m)));
}

void TestRobustness::saturatedSensor_importWarnsPerAxisAndResultIsFinite()
{
    // The simulated walk's foot turns at up to about 3.9 rad/s; a +-3.2 rad/s gyro clips it.
    const Recording walk = clipped(simulatedWalk(), 16.0, 3.2);
    const std::vector<std::string> warnings = describeSaturation(walk.samples);
    QVERIFY(!warnings.empty());
    QVERIFY2(QString::fromStdString(warnings.front()).contains("gyroscope's y axis reads exactly -3.2 rad/s"),
             warnings.front().c_str());

    std::istringstream csv(asCsv(walk));
    const ImportResult imported = importStream(csv, csv.str().size(), "clipped.csv");
    QVERIFY2(imported.ok(), imported.ok() ? "" : imported.error->message.c_str());
    const std::vector<std::string>& importWarnings = imported.recording.warnings;
    QVERIFY(std::any_of(importWarnings.begin(), importWarnings.end(), [](const std::string& warning) {
        return warning.find("the sensor was saturated there") != std::string::npos;
    }));
    const PipelineOutput output = runPipeline(imported.recording, Parameters());
    QVERIFY2(output.error.empty(), output.error.c_str());
    QVERIFY(allFinite(output.result));
}

void TestRobustness::noiseFreeStillSensor_isNotSaturated()
{
    WalkSimulatorConfig config;  // no noise: every sample of the rest is the same
    const SimulatedWalk walk = simulateWalk(straightLinePath(5.0), config);
    QVERIFY(describeSaturation(walk.recording.samples).empty());
    QVERIFY(describeSaturation(simulatedWalk().samples).empty());
}

void TestRobustness::neverMoving_warnsThatTheSensorHardlyMoved()
{
    const Recording walk = simulatedWalk();
    Recording still = walk;
    still.samples.assign(3000, walk.samples.front());
    for (std::size_t k = 0; k < still.samples.size(); ++k)
        still.samples[k].time_s = 0.01 * static_cast<double>(k);
    const PipelineOutput output = runPipeline(still, Parameters());
    QVERIFY2(output.error.empty(), output.error.c_str());
    QVERIFY(allFinite(output.result));
    QVERIFY(output.result.summary.pathLength_m < 0.05);
    QVERIFY(anyWarningContains(output.result.warnings, "the sensor hardly moved"));
    QVERIFY(!anyWarningContains(output.result.warnings, "does not find the foot at rest"));
}

void TestRobustness::noInitialRest_warnsAndStaysFinite()
{
    WalkSimulatorConfig config = mtiClassSensor(100.0, 3);
    config.initialStill_s = 0.0;
    config.finalStill_s = 0.0;
    const PipelineOutput output = runPipeline(simulateWalk(straightLinePath(20.0), config).recording, Parameters());
    QVERIFY2(output.error.empty(), output.error.c_str());
    QVERIFY(allFinite(output.result));
    QVERIFY(anyWarningContains(output.result.warnings, "starts mid-walk"));
}

void TestRobustness::extremeRates_giveTheWalksLength_data()
{
    QTest::addColumn<double>("rate_hz");
    QTest::newRow("25 Hz") << 25.0;
    QTest::newRow("1 kHz") << 1000.0;
}

void TestRobustness::extremeRates_giveTheWalksLength()
{
    QFETCH(double, rate_hz);
    const PipelineOutput output = runPipeline(simulatedWalk(rate_hz), Parameters());
    QVERIFY2(output.error.empty(), output.error.c_str());
    QVERIFY(allFinite(output.result));
    QVERIFY2(std::abs(output.result.summary.pathLength_m - 20.0) < 0.5,
             qPrintable(QString::number(output.result.summary.pathLength_m)));
    QVERIFY(output.result.warnings.empty());
}

QTEST_APPLESS_MAIN(TestRobustness)
#include "tst_robustness.moc"
