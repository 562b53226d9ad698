#include "detect/StanceDetector.h"

#include <QtTest>

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
