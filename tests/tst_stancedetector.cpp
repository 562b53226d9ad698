#include "TestData.h"
#include "detect/StanceDetector.h"
#include "detect/StanceFlagsAhead.h"
#include "io/ColumnMapGuess.h"
#include "io/Import.h"
#include "nav/Alignment.h"

#include <QDirIterator>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <stdexcept>

using namespace footpath;

namespace {

std::vector<double> uniformTimes(std::size_t n, double rate_hz)
{
    std::vector<double> times(n);
    for (std::size_t k = 0; k < n; ++k)
        times[k] = static_cast<double>(k) / rate_hz;
    return times;
}

std::vector<ImuSample> restingSamples(std::size_t n, double rate_hz)
{
    std::vector<ImuSample> samples(n);
    const std::vector<double> times = uniformTimes(n, rate_hz);
    for (std::size_t k = 0; k < n; ++k) {
        samples[k].time_s = times[k];
        samples[k].acc_mps2 = Eigen::Vector3d(0, 0, 9.81);
    }
    return samples;
}

std::vector<std::uint8_t> flags(const std::string& pattern)
{
    std::vector<std::uint8_t> out;
    for (char ch : pattern)
        out.push_back(ch == '1');
    return out;
}

std::string pattern(const std::vector<std::uint8_t>& values)
{
    std::string out;
    for (auto v : values)
        out += v ? '1' : '0';
    return out;
}


// A plain statistic detector written from the definitions in detect/StatisticDetectors.h, sample
// by sample, to check the streaming one against: every window found by scanning outwards from its
// centre, the running minimum and maximum by looking at every value in the window.

constexpr double kWindowTolerance_s = 1e-9;  // timestamps are rounded decimals (StatisticDetectors.cpp)

/// The first and last index within +-half_s of sample k's time.
std::pair<std::size_t, std::size_t> centredWindow(const std::vector<double>& times, std::size_t k, double half_s)
{
    std::size_t first = k;
    while (first > 0 && times[first - 1] >= times[k] - half_s - kWindowTolerance_s)
        --first;
    std::size_t last = k;
    while (last + 1 < times.size() && times[last + 1] <= times[k] + half_s + kWindowTolerance_s)
        ++last;
    return {first, last};
}

/// SHOE, ARED or AMVD over samples[first..last], normalised by the noise variances.
double referenceStatistic(const std::vector<ImuSample>& samples, std::size_t first, std::size_t last,
                          const Parameters& params)
{
    const double count = static_cast<double>(last - first + 1);
    Eigen::Vector3d meanAcc = Eigen::Vector3d::Zero();
    for (std::size_t j = first; j <= last; ++j)
        meanAcc += samples[j].acc_mps2 / count;
    const Eigen::Vector3d gravity = params.gravity_mps2 * meanAcc.normalized();
    const double varAcc = params.zv_sigma_acc_mps2 * params.zv_sigma_acc_mps2;
    const double varGyr = params.zv_sigma_gyr_radps * params.zv_sigma_gyr_radps;
    double sum = 0.0;
    for (std::size_t j = first; j <= last; ++j) {
        const ImuSample& s = samples[j];
        switch (params.detectorKind()) {
        case DetectorKind::Ared:
            sum += s.gyr_radps.squaredNorm() / varGyr;
            break;
        case DetectorKind::Amvd:
            sum += (s.acc_mps2 - meanAcc).squaredNorm() / varAcc;
            break;
        default:
            sum += (s.acc_mps2 - gravity).squaredNorm() / varAcc + s.gyr_radps.squaredNorm() / varGyr;
        }
    }
    return sum / count;
}

struct ReferenceFlags {
    std::vector<double> logStatistic;
    std::vector<double> logThreshold;
    std::vector<std::uint8_t> c;
    std::vector<std::uint8_t> stance;
};

ReferenceFlags referenceDetector(const std::vector<ImuSample>& samples, const Parameters& params)
{
    const std::size_t n = samples.size();
    std::vector<double> times(n);
    for (std::size_t k = 0; k < n; ++k)
        times[k] = samples[k].time_s;
    ReferenceFlags out;
    std::vector<float> stored(n);  // the detector keeps the log statistic as a float
    for (std::size_t k = 0; k < n; ++k) {
        const auto [first, last] = centredWindow(times, k, params.zv_window_s / 2.0);
        out.logStatistic.push_back(std::log10(std::max(referenceStatistic(samples, first, last, params), 1e-12)));
        stored[k] = static_cast<float>(out.logStatistic[k]);
    }
    for (std::size_t k = 0; k < n; ++k) {
        double threshold = params.zv_log_threshold;
        if (params.zv_adaptive) {
            const auto [first, last] = centredWindow(times, k, params.zv_adapt_window_s / 2.0);
            const double lowest = *std::min_element(stored.begin() + first, stored.begin() + last + 1);
            const double highest = *std::max_element(stored.begin() + first, stored.begin() + last + 1);
            threshold = std::clamp(lowest + params.zv_adapt_offset_dec + params.zv_adapt_fraction * (highest - lowest),
                                   params.zv_log_always, params.zv_log_never);
        }
        out.logThreshold.push_back(threshold);
        out.c.push_back(stored[k] < static_cast<float>(threshold) ? 1 : 0);
    }
    out.stance = out.c;
    for (std::size_t start = 0; start < n; ++start) {  // runs of c shorter than zv_min_stance_s are dropped
        if (!out.c[start] || (start > 0 && out.c[start - 1]))
            continue;
        std::size_t end = start;
        while (end + 1 < n && out.c[end + 1])
            ++end;
        if (times[end] - times[start] < params.zv_min_stance_s - kWindowTolerance_s)
            std::fill(out.stance.begin() + start, out.stance.begin() + end + 1, 0);
    }
    return out;
}

/// Half a float's spacing at value: how far a double may lie from the float it was rounded to.
double halfFloatSpacing(float value)
{
    return 0.5 * (std::nextafter(std::abs(value), INFINITY) - std::abs(value));
}

/// Every shared recording the importer reads, headerless logs with the column map it is sure of.
std::vector<std::pair<QString, Recording>> sharedRecordings()
{
    std::vector<std::pair<QString, Recording>> recordings;
    QDirIterator files(datasetsDir(), {"*.csv", "*.txt", "*.TXT", "*.mtb"}, QDir::Files, QDirIterator::Subdirectories);
    while (files.hasNext()) {
        const std::string path = files.next().toStdString();
        ImportOptions options;
        ImportResult read = importRecording(path, options);
        if (!read.ok()) {
            const ColumnMapGuess guess = guessColumnMap(path, options);
            if (!guess.confident)
                continue;
            options.columnMap = guess.columnMap;
            read = importRecording(path, options);
        }
        if (read.ok() && read.recording.samples.size() > 100)
            recordings.emplace_back(QDir(datasetsDir()).relativeFilePath(files.filePath()), std::move(read.recording));
    }
    return recordings;
}

/// The statistic detectors' settings checked on the real recordings.
std::vector<std::pair<const char*, Parameters>> statisticDetectorSettings()
{
    Parameters shoe;
    Parameters ared;
    ared.detector = static_cast<int>(DetectorKind::Ared);
    Parameters amvd;
    amvd.detector = static_cast<int>(DetectorKind::Amvd);
    Parameters fixedThreshold;
    fixedThreshold.zv_adaptive = false;
    Parameters offTheGrid;  // windows that end between samples, a minimum stance of a few samples
    offTheGrid.zv_window_s = 0.0523;
    offTheGrid.zv_adapt_window_s = 0.777;
    offTheGrid.zv_min_stance_s = 0.0331;
    return {{"shoe", shoe}, {"ared", ared}, {"amvd", amvd}, {"fixed threshold", fixedThreshold},
            {"windows off the sample grid", offTheGrid}};
}

/// Rest and swing in turn (0.5 s and 0.6 s at 100 Hz) for count samples: many stances, many of the
/// statistic detectors' batches.
std::vector<ImuSample> alternatingWalk(std::size_t count)
{
    std::vector<ImuSample> samples = restingSamples(count, 100.0);
    for (std::size_t k = 0; k < count; ++k) {
        if (k % 110 < 50)
            continue;
        const double phase = static_cast<double>(k % 110 - 50) / 60.0 * 2.0 * M_PI;
        samples[k].gyr_radps = Eigen::Vector3d(0.2, 3.0 * std::sin(phase), 0.1);
        samples[k].acc_mps2 = Eigen::Vector3d(4.0 * std::sin(2.0 * phase), 0.5, 9.81 + 6.0 * std::cos(phase));
    }
    return samples;
}

std::vector<std::pair<const char*, Parameters>> everyDetector()
{
    std::vector<std::pair<const char*, Parameters>> settings = statisticDetectorSettings();
    settings.emplace_back("paper C1/C2/C3", guo2015Parameters());
    return settings;
}

}  // namespace

class TestStanceDetector : public QObject {
    Q_OBJECT
private slots:
    void c1BoundsAreStrict_data()
    {
        QTest::addColumn<double>("norm");
        QTest::addColumn<bool>("expected");
        QTest::newRow("at rest") << 9.81 << true;
        QTest::newRow("exactly a_min") << 9.0 << false;
        QTest::newRow("just above a_min") << 9.001 << true;
        QTest::newRow("exactly a_max") << 11.0 << false;
        QTest::newRow("heel strike") << 25.0 << false;
    }
    void c1BoundsAreStrict()
    {
        QFETCH(double, norm);
        QFETCH(bool, expected);
        std::vector<ImuSample> samples = restingSamples(5, 100.0);
        samples[2].acc_mps2 = Eigen::Vector3d(0.6, 0.0, 0.8) * norm;
        const StanceFlags result = detectStance(samples, guo2015Parameters());
        QCOMPARE(bool(result.c1[2]), expected);
        QCOMPARE(bool(result.c1[1]), true);
    }

    void c3UsesTheRateMagnitude()
    {
        std::vector<ImuSample> samples = restingSamples(3, 100.0);
        samples[0].gyr_radps = Eigen::Vector3d(0.6, 0.6, 0.6);  // |w| = 1.04 > 1
        samples[1].gyr_radps = Eigen::Vector3d(0.5, 0.5, 0.5);  // |w| = 0.87 < 1
        const StanceFlags result = detectStance(samples, guo2015Parameters());
        QCOMPARE(pattern(result.c3), std::string("011"));
    }

    void c2WindowCoversExactlyTheHalfWindowEachSide()
    {
        // One spike at sample 50 of a 100 Hz walk: with window_half_s = 0.15 s it must raise the
        // std of samples 35..65 and of no other.
        std::vector<ImuSample> samples = restingSamples(101, 100.0);
        samples[50].acc_mps2.z() = 20.0;
        const StanceFlags result = detectStance(samples, guo2015Parameters());
        for (std::size_t k = 0; k < samples.size(); ++k) {
            const bool insideWindow = k >= 35 && k <= 65;
            QVERIFY2(bool(result.c2[k]) == !insideWindow, qPrintable(QString("sample %1").arg(k)));
        }
    }

    void c2WindowIsTruncatedAtTheEnds()
    {
        // A spike at the first sample: the window of sample 0 holds samples 0..15 only; the std of
        // two values {a, b} over n samples is |a - b| sqrt(n - 1) / n.
        std::vector<double> times = uniformTimes(40, 100.0);
        std::vector<double> values(40, 9.81);
        values[0] = 10.81;
        const std::vector<double> stds = centredStdDev(times, values, 0.15);
        QVERIFY(std::abs(stds[0] - std::sqrt(15.0) / 16.0) < 1e-12);
        QVERIFY(std::abs(stds[15] - std::sqrt(30.0) / 31.0) < 1e-12);
        QCOMPARE(stds[16], 0.0);
    }

    void windowsAreDurationsNotSampleCounts()
    {
        // The same spike at 200 Hz reaches 0.15 s = 30 samples each side.
        std::vector<ImuSample> samples = restingSamples(201, 200.0);
        samples[100].acc_mps2.z() = 20.0;
        const StanceFlags result = detectStance(samples, guo2015Parameters());
        QCOMPARE(bool(result.c2[70]), false);
        QCOMPARE(bool(result.c2[69]), true);
        QCOMPARE(bool(result.c2[130]), false);
        QCOMPARE(bool(result.c2[131]), true);
    }

    void gapsShrinkTheWindowInSamples()
    {
        // A 1 s gap: the samples after it must not see the spike before it.
        std::vector<ImuSample> samples = restingSamples(40, 100.0);
        for (std::size_t k = 20; k < samples.size(); ++k)
            samples[k].time_s += 1.0;
        samples[19].acc_mps2.z() = 20.0;
        const StanceFlags result = detectStance(samples, guo2015Parameters());
        QCOMPARE(bool(result.c2[18]), false);
        QCOMPARE(bool(result.c2[20]), true);
    }

    void medianFilter_data()
    {
        QTest::addColumn<QString>("input");
        QTest::addColumn<QString>("expected");
        QTest::addColumn<double>("window");
        // 0.05 s at 100 Hz: a window of 5 samples (2 each side).
        QTest::newRow("isolated one removed") << "0000100000" << "0000000000" << 0.05;
        QTest::newRow("isolated zero filled") << "1111011111" << "1111111111" << 0.05;
        QTest::newRow("two ones of five removed") << "0001100000" << "0000000000" << 0.05;
        QTest::newRow("three ones of five kept") << "0001110000" << "0001110000" << 0.05;
        QTest::newRow("edge: tie keeps input") << "1100000000" << "1100000000" << 0.05;
        QTest::newRow("edge: one of three removed") << "0100000000" << "0000000000" << 0.05;
        QTest::newRow("zero window is identity") << "0100110100" << "0100110100" << 0.0;
    }
    void medianFilter()
    {
        QFETCH(QString, input);
        QFETCH(QString, expected);
        QFETCH(double, window);
        const std::vector<std::uint8_t> in = flags(input.toStdString());
        const std::vector<std::uint8_t> out = footpath::medianFilter(uniformTimes(in.size(), 100.0), in, window);
        QCOMPARE(QString::fromStdString(pattern(out)), expected);
    }

    void statisticDetectorMatchesAPlainReferenceOnTheSharedRecordings()
    {
        FOOTPATH_REQUIRE_DATASETS();
        const auto recordings = sharedRecordings();
        QVERIFY2(recordings.size() >= 12, "the pyshoe-vicon trials at least");
        std::size_t checked = 0;
        for (const auto& [name, recording] : recordings) {
            for (const auto& [setting, params] : statisticDetectorSettings()) {
                const StanceFlags flags = detectStance(recording.samples, params);
                const ReferenceFlags expected = referenceDetector(recording.samples, params);
                const std::size_t n = recording.samples.size();
                QCOMPARE(flags.stance.size(), n);
                QCOMPARE(flags.logStatistic.size(), n);
                for (std::size_t k = 0; k < n; ++k) {
                    const QByteArray where = QStringLiteral("%1, %2, sample %3").arg(name, setting).arg(k).toUtf8();
                    QVERIFY2(std::abs(flags.logStatistic[k] - expected.logStatistic[k])
                                 <= halfFloatSpacing(flags.logStatistic[k]) + 1e-9,
                             where.constData());
                    QVERIFY2(std::abs(flags.logThreshold[k] - expected.logThreshold[k])
                                 <= halfFloatSpacing(flags.logThreshold[k]) + 1e-9,
                             where.constData());
                    QVERIFY2(flags.c[k] == expected.c[k], where.constData());
                    QVERIFY2(flags.stance[k] == expected.stance[k], where.constData());
                    QVERIFY2(flags.c1[k] == flags.c[k] && flags.c2[k] == flags.c[k] && flags.c3[k] == flags.c[k],
                             where.constData());
                }
                checked += n;
            }
        }
        qInfo("%zu recordings, %zu samples checked", recordings.size(), checked);
    }

    void statisticDetectorLiveEqualsOfflineOnTheSharedRecordings()
    {
        FOOTPATH_REQUIRE_DATASETS();
        for (const auto& [name, recording] : sharedRecordings()) {
            for (const auto& [setting, params] : statisticDetectorSettings()) {
                const StanceFlags offline = detectStance(recording.samples, params);
                StanceFlags live;
                std::deque<SampleStanceFlags> decided;
                const std::unique_ptr<CausalStanceDecider> detector = makeCausalStanceDetector(params);
                for (const ImuSample& sample : recording.samples)
                    detector->push(sample, decided);
                detector->finish(decided);
                for (const SampleStanceFlags& sample : decided)
                    appendFlags(live, sample);
                const QByteArray where = QStringLiteral("%1, %2").arg(name, setting).toUtf8();
                QVERIFY2(live.c == offline.c && live.stance == offline.stance, where.constData());
                QVERIFY2(live.logStatistic == offline.logStatistic, where.constData());
                QVERIFY2(live.logThreshold == offline.logThreshold, where.constData());
            }
        }
    }

    void flagsDecidedAheadAreFinalWhenTheReaderGetsThem()
    {
        // The filter follows the detector's thread sample by sample (runPipeline): each sample's
        // flags it is allowed to read must already be detectStance's, for every detector.
        const std::vector<ImuSample> samples = alternatingWalk(20000);
        for (const auto& [setting, params] : everyDetector()) {
            const StanceFlags expected = detectStance(samples, params);
            std::size_t stanceStarts = 0;
            for (std::size_t k = 1; k < samples.size(); ++k)
                stanceStarts += expected.stance[k] && !expected.stance[k - 1];
            QVERIFY2(stanceStarts > 20, setting);  // flags that change in most of the detector's batches
            for (const auto mode : {StanceFlagsAhead::Mode::Concurrent, StanceFlagsAhead::Mode::First}) {
                StanceFlags flags;
                StanceFlagsAhead ahead(samples, params, flags, mode);
                QCOMPARE(waitForAlignmentFlags(ahead, samples, flags.stance, 1.0), std::size_t(0));  // starts at rest
                std::size_t differing = 0;
                for (std::size_t k = 0; k < samples.size(); ++k) {
                    ahead.waitFor(k + 1);
                    const SampleStanceFlags read = flagsAt(flags, k);
                    differing += read.stance != expected.stance[k] || read.c != expected.c[k]
                                 || read.logStatistic != expected.logStatistic[k]
                                 || read.logThreshold != expected.logThreshold[k];
                }
                QVERIFY2(differing == 0, setting);
                ahead.waitForAll();
                QVERIFY2(flags.stance == expected.stance && flags.c1 == expected.c1 && flags.c2 == expected.c2
                             && flags.c3 == expected.c3,
                         setting);
            }
        }
    }

    void alignmentWaitsForTheFirstStanceAndItsPeriod()
    {
        // A walk that starts moving: the alignment reads the flags up to its first stance and the
        // alignment period after it; one that never rests: every flag, and it starts at 0.
        std::vector<ImuSample> samples = alternatingWalk(5000);
        samples.erase(samples.begin(), samples.begin() + 60);  // starts mid-swing
        const Parameters params;
        const StanceFlags expected = detectStance(samples, params);
        StanceFlags flags;
        StanceFlagsAhead ahead(samples, params, flags, StanceFlagsAhead::Mode::Concurrent);
        const std::size_t first = waitForAlignmentFlags(ahead, samples, flags.stance, params.alignment_s);
        QVERIFY(first > 0);
        QCOMPARE(first, alignmentStart(expected.stance));

        std::vector<ImuSample> moving = restingSamples(3000, 100.0);
        for (std::size_t k = 0; k < moving.size(); ++k)
            moving[k].gyr_radps = Eigen::Vector3d(0.0, 4.0 + std::sin(0.1 * static_cast<double>(k)), 0.0);
        StanceFlags none;
        StanceFlagsAhead never(moving, guo2015Parameters(), none, StanceFlagsAhead::Mode::Concurrent);
        QCOMPARE(waitForAlignmentFlags(never, moving, none.stance, 1.0), std::size_t(0));
        QCOMPARE(std::count(none.stance.begin(), none.stance.end(), 1), 0);
    }

    void aReaderThatLeavesEarlyStopsTheDetector()
    {
        // A cancelled run destroys the flags before the detector is done: it must stop and be
        // joined, not run on into freed memory (ThreadSanitizer and AddressSanitizer builds).
        const std::vector<ImuSample> samples = alternatingWalk(200000);
        for (int run = 0; run < 20; ++run) {
            StanceFlags flags;
            StanceFlagsAhead ahead(samples, Parameters(), flags, StanceFlagsAhead::Mode::Concurrent);
            if (run % 2 == 1)
                ahead.waitFor(1);
        }
    }

    void workAfterTheFlagsSeesThemAllAndItsFailureReachesTheReader()
    {
        const std::vector<ImuSample> samples = alternatingWalk(50000);
        const StanceFlags expected = detectStance(samples, Parameters());
        for (const auto mode : {StanceFlagsAhead::Mode::Concurrent, StanceFlagsAhead::Mode::First}) {
            StanceFlags flags;
            std::size_t stanceSeen = 0;
            int runs = 0;
            StanceFlagsAhead ahead(samples, Parameters(), flags, mode, [&] {
                ++runs;
                stanceSeen = static_cast<std::size_t>(std::count(flags.stance.begin(), flags.stance.end(), 1));
            });
            ahead.waitForAfterFlags();
            QCOMPARE(runs, 1);
            QCOMPARE(stanceSeen, static_cast<std::size_t>(std::count(expected.stance.begin(), expected.stance.end(), 1)));
            QVERIFY(flags.stance == expected.stance);
        }
        for (const auto mode : {StanceFlagsAhead::Mode::Concurrent, StanceFlagsAhead::Mode::First}) {
            StanceFlags flags;
            StanceFlagsAhead failing(samples, Parameters(), flags, mode, [] { throw std::runtime_error("out of memory"); });
            failing.waitForAll();  // the flags are fine; only the work after them failed
            QVERIFY_THROWS_EXCEPTION(std::runtime_error, failing.waitForAfterFlags());
        }
    }

    void stanceIsTheFilteredConjunction()
    {
        std::vector<ImuSample> samples = restingSamples(100, 100.0);
        for (std::size_t k = 40; k < 60; ++k)
            samples[k].gyr_radps = Eigen::Vector3d(0, 3.0, 0);
        samples[80].gyr_radps = Eigen::Vector3d(0, 3.0, 0);  // one sample: removed by the median
        const StanceFlags result = detectStance(samples, guo2015Parameters());
        QCOMPARE(bool(result.c[80]), false);
        QCOMPARE(bool(result.stance[80]), true);
        for (std::size_t k = 40; k < 60; ++k)
            QVERIFY(!result.stance[k]);
        QVERIFY(result.stance[10] && result.stance[95]);
    }
};

QTEST_APPLESS_MAIN(TestStanceDetector)
#include "tst_stancedetector.moc"
