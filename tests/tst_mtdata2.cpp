// MTData2 payloads: the documented examples of docs/xbus.md sections 8.3-8.5 decode to
// their stated values, every precision round-trips, frame bits are read, unknown identifiers are
// skipped by their size, and malformed payloads are reported with their offset.
#include "xbus/MtData2.h"

#include <QtTest>

#include <cmath>
#include <memory>

using namespace footpath;

Q_DECLARE_METATYPE(footpath::XdaPrecision)
Q_DECLARE_METATYPE(footpath::XdaCoordinateFrame)

namespace {

std::vector<std::uint8_t> bytes(const QByteArray& hex)
{
    const QByteArray raw = QByteArray::fromHex(hex);
    return {raw.begin(), raw.end()};
}

bool near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tolerance)
{
    return (actual - expected).cwiseAbs().maxCoeff() <= tolerance;
}

bool near(const Eigen::Quaterniond& actual, const Eigen::Quaterniond& expected, double tolerance)
{
    return (actual.coeffs() - expected.coeffs()).cwiseAbs().maxCoeff() <= tolerance;
}

/// A sample with every quantity, values that none of the precisions represents exactly.
MtData2Sample fullSample()
{
    MtData2Sample s;
    s.packetCounter = 65535;
    s.sampleTimeFine = 4294967295u;
    s.sampleTimeCoarse = 429496;
    s.acceleration = Eigen::Vector3d(0.1, -1.2345678, 9.80665);
    s.freeAcceleration = Eigen::Vector3d(-0.3, 0.2, 0.01);
    s.rateOfTurn = Eigen::Vector3d(3.14159, -0.001, 0.5);
    s.magneticField = Eigen::Vector3d(0.45, -0.12, 0.87);
    s.deltaV = Eigen::Vector3d(0.00981, 0.0001, -0.0002);
    s.deltaQ = Eigen::Quaterniond(0.99999, 0.001, -0.002, 0.003);
    s.pressure_pa = 100062.0;
    s.quaternion = Eigen::Quaterniond(0.7071, 0.0, 0.7071, 0.0);
    s.euler_deg = Eigen::Vector3d(-179.9, 45.5, 90.25);
    s.statusWord = 0x00400003;
    s.statusByte = 0x03;
    s.temperature_degC = 23.456;
    s.orientationFrame = XdaCoordinateFrame::Nwu;
    s.freeAccelerationFrame = XdaCoordinateFrame::Ned;
    return s;
}

}  // namespace

class TestMtData2 : public QObject {
    Q_OBJECT
private slots:
    void realMti710Payload()  // section 8.3
    {
        const MtData2Decoded d = decodeMtData2(bytes("10 20 02 DF C5 10 60 04 00 45 9D A0 40 20 0C BE DC 9A FA 3F 54 9F "
                                                     "37 41 1C BB 70 80 20 0C BB AA 5C 80 3B 8C 55 01 BB 81 33 00 E0 20 "
                                                     "04 00 00 00 81"));
        QVERIFY2(d.ok(), d.error.c_str());
        QCOMPARE(*d.sample.packetCounter, std::uint16_t(57285));
        QCOMPARE(*d.sample.sampleTimeFine, std::uint32_t(4562336));
        QVERIFY(near(*d.sample.acceleration, Eigen::Vector3d(-0.43087, 0.83055, 9.79576), 5e-6));
        QVERIFY(near(*d.sample.rateOfTurn, Eigen::Vector3d(-0.005199, 0.004283, -0.003943), 5e-7));
        QCOMPARE(*d.sample.statusWord, std::uint32_t(0x81));
        QVERIFY(!d.sample.magneticField);
        QVERIFY(!d.sample.freeAcceleration);
        QVERIFY(!d.sample.quaternion);
        QCOMPARE(d.unknownItems, std::size_t(0));
    }

    void constructedPayload()  // section 8.4, values exact in float32
    {
        const MtData2Decoded d = decodeMtData2(bytes("10 20 02 04 D2 10 60 04 00 57 47 2E 40 20 0C 3E 80 00 00 BF 00 00 "
                                                     "00 41 1D 00 00 80 20 0C 3C 80 00 00 BD 00 00 00 00 00 00 00 C0 20 "
                                                     "0C 3F 00 00 00 BE 80 00 00 3F 80 00 00 E0 20 04 00 00 00 03"));
        QVERIFY2(d.ok(), d.error.c_str());
        QCOMPARE(*d.sample.packetCounter, std::uint16_t(1234));
        QCOMPARE(*d.sample.sampleTimeFine, std::uint32_t(5719854));
        QCOMPARE(*d.sample.acceleration, Eigen::Vector3d(0.25, -0.5, 9.8125));
        QCOMPARE(*d.sample.rateOfTurn, Eigen::Vector3d(0.015625, -0.03125, 0.0));
        QCOMPARE(*d.sample.magneticField, Eigen::Vector3d(0.5, -0.25, 1.0));
        QCOMPARE(*d.sample.statusWord, std::uint32_t(3));
    }

    void float64NedQuaternion()  // section 8.4, identifier 0x2017
    {
        const MtData2Decoded d = decodeMtData2(bytes("10 20 02 04 D2 20 17 20 3F F0 00 00 00 00 00 00" + QByteArray(48, '0')));
        QVERIFY2(d.ok(), d.error.c_str());
        QCOMPARE(*d.sample.packetCounter, std::uint16_t(1234));
        QVERIFY(near(*d.sample.quaternion, Eigen::Quaterniond(1, 0, 0, 0), 0.0));
        QCOMPARE(d.sample.orientationFrame, XdaCoordinateFrame::Ned);
    }

    void realMti300Payload()  // section 8.5
    {
        const MtData2Decoded d = decodeMtData2(bytes("10 20 02 46 82 10 60 04 01 C4 FC 3E 20 10 10 3F 71 CE 6C BE A5 6B "
                                                     "CF 3C 61 3B D8 BD 69 1D 25 E0 20 04 00 40 00 03"));
        QVERIFY2(d.ok(), d.error.c_str());
        QCOMPARE(*d.sample.packetCounter, std::uint16_t(18050));
        QCOMPARE(*d.sample.sampleTimeFine, std::uint32_t(29686846));
        QVERIFY(near(*d.sample.quaternion, Eigen::Quaterniond(0.94456, -0.32309, 0.01375, -0.05691), 5e-6));
        QCOMPARE(d.sample.orientationFrame, XdaCoordinateFrame::Enu);
        QCOMPARE(*d.sample.statusWord, std::uint32_t(0x00400003));
        QVERIFY(!d.sample.acceleration);
    }

    void everyPrecisionRoundTrips_data()
    {
        QTest::addColumn<XdaPrecision>("precision");
        QTest::addColumn<double>("tolerance");
        QTest::addColumn<int>("accItemSize");
        QTest::newRow("float32") << XdaPrecision::Float32 << 1e-6 << 12;  // relative to values up to ~180
        QTest::newRow("fp12.20") << XdaPrecision::Fp1220 << std::ldexp(1.0, -21) << 12;
        QTest::newRow("fp16.32") << XdaPrecision::Fp1632 << std::ldexp(1.0, -33) << 18;
        QTest::newRow("float64") << XdaPrecision::Float64 << 0.0 << 24;
    }
    void everyPrecisionRoundTrips()
    {
        QFETCH(XdaPrecision, precision);
        QFETCH(double, tolerance);
        QFETCH(int, accItemSize);
        const MtData2Sample in = fullSample();
        const std::vector<std::uint8_t> payload = encodeMtData2(in, precision);
        const MtData2Decoded d = decodeMtData2(payload);
        QVERIFY2(d.ok(), d.error.c_str());
        QCOMPARE(d.unknownItems, std::size_t(0));
        const MtData2Sample& out = d.sample;
        const double relative = precision == XdaPrecision::Float32 ? 1e-7 : 0.0;
        auto within = [&](double value) { return tolerance + relative * std::abs(value); };
        QCOMPARE(*out.packetCounter, *in.packetCounter);
        QCOMPARE(*out.sampleTimeFine, *in.sampleTimeFine);
        QCOMPARE(*out.sampleTimeCoarse, *in.sampleTimeCoarse);
        QCOMPARE(*out.statusWord, *in.statusWord);
        QCOMPARE(*out.statusByte, *in.statusByte);
        QCOMPARE(*out.pressure_pa, *in.pressure_pa);
        QVERIFY(near(*out.acceleration, *in.acceleration, within(10.0)));
        QVERIFY(near(*out.freeAcceleration, *in.freeAcceleration, within(1.0)));
        QVERIFY(near(*out.rateOfTurn, *in.rateOfTurn, within(4.0)));
        QVERIFY(near(*out.magneticField, *in.magneticField, within(1.0)));
        QVERIFY(near(*out.deltaV, *in.deltaV, within(0.01)));
        QVERIFY(near(*out.deltaQ, *in.deltaQ, within(1.0)));
        QVERIFY(near(*out.quaternion, *in.quaternion, within(1.0)));
        QVERIFY(near(*out.euler_deg, *in.euler_deg, within(180.0)));
        QVERIFY(std::abs(*out.temperature_degC - *in.temperature_degC) <= within(25.0));
        QCOMPARE(out.orientationFrame, XdaCoordinateFrame::Nwu);
        QCOMPARE(out.freeAccelerationFrame, XdaCoordinateFrame::Ned);
        // The acceleration item carries the precision in its identifier and sizes its values by it.
        const std::vector<std::uint8_t> accOnly = encodeMtData2([] {
            MtData2Sample s;
            s.acceleration = Eigen::Vector3d(1, 2, 3);
            return s;
        }(), precision);
        QCOMPARE(int(accOnly.size()), 3 + accItemSize);
        QCOMPARE((accOnly[0] << 8) | accOnly[1], 0x4020 | int(precision));
        QCOMPARE(int(accOnly[2]), accItemSize);
    }

    void fixedPointBytes_data()
    {
        QTest::addColumn<XdaPrecision>("precision");
        QTest::addColumn<double>("value");
        QTest::addColumn<QByteArray>("encoded");
        QTest::newRow("fp16.32 -1.5 (section 1.2)") << XdaPrecision::Fp1632 << -1.5 << QByteArray("80000000fffe");
        QTest::newRow("fp16.32 1.25") << XdaPrecision::Fp1632 << 1.25 << QByteArray("400000000001");
        QTest::newRow("fp12.20 1.0") << XdaPrecision::Fp1220 << 1.0 << QByteArray("00100000");
        QTest::newRow("fp12.20 -1.0") << XdaPrecision::Fp1220 << -1.0 << QByteArray("fff00000");
        QTest::newRow("float32 9.8125") << XdaPrecision::Float32 << 9.8125 << QByteArray("411d0000");
        QTest::newRow("float64 1.0") << XdaPrecision::Float64 << 1.0 << QByteArray("3ff0000000000000");
    }
    void fixedPointBytes()
    {
        QFETCH(XdaPrecision, precision);
        QFETCH(double, value);
        QFETCH(QByteArray, encoded);
        std::vector<std::uint8_t> out;
        appendXdaReal(out, value, precision);
        QCOMPARE(QByteArray(reinterpret_cast<const char*>(out.data()), int(out.size())).toHex(), encoded);
        QCOMPARE(out.size(), xdaValueSize(precision));
        XbusPayloadReader reader(out.data(), out.size());
        double decoded = 0.0;
        QVERIFY(readXdaReal(reader, precision, decoded));
        QCOMPARE(decoded, value);
    }

    void fixedPointSaturates()
    {
        std::vector<std::uint8_t> out;
        appendXdaReal(out, 5000.0, XdaPrecision::Fp1220);  // range is [-2048, 2048)
        appendXdaReal(out, -1e9, XdaPrecision::Fp1632);     // range is [-32768, 32768)
        XbusPayloadReader reader(out.data(), out.size());
        double high = 0.0;
        double low = 0.0;
        QVERIFY(readXdaReal(reader, XdaPrecision::Fp1220, high));
        QVERIFY(readXdaReal(reader, XdaPrecision::Fp1632, low));
        QVERIFY(high > 2047.99 && high < 2048.0);
        QCOMPARE(low, -32768.0);
    }

    void frameBits_data()
    {
        QTest::addColumn<QByteArray>("payload");
        QTest::addColumn<XdaCoordinateFrame>("frame");
        const QByteArray euler = " 0C 3F 80 00 00 40 00 00 00 40 40 00 00";  // (1, 2, 3)
        QTest::newRow("Euler ENU 0x2030") << "20 30" + euler << XdaCoordinateFrame::Enu;
        QTest::newRow("Euler NED 0x2034") << "20 34" + euler << XdaCoordinateFrame::Ned;
        QTest::newRow("Euler NWU 0x2038") << "20 38" + euler << XdaCoordinateFrame::Nwu;
    }
    void frameBits()
    {
        QFETCH(QByteArray, payload);
        QFETCH(XdaCoordinateFrame, frame);
        const MtData2Decoded d = decodeMtData2(bytes(payload));
        QVERIFY2(d.ok(), d.error.c_str());
        QCOMPARE(*d.sample.euler_deg, Eigen::Vector3d(1, 2, 3));
        QCOMPARE(d.sample.orientationFrame, frame);
        MtData2Sample s;
        s.euler_deg = Eigen::Vector3d(1, 2, 3);
        s.orientationFrame = frame;
        QCOMPARE(encodeMtData2(s), bytes(payload));
    }

    void reservedFrameBitsAreSkippedAsUnknown()
    {
        const MtData2Decoded d = decodeMtData2(bytes("20 3C 0C 3F 80 00 00 40 00 00 00 40 40 00 00 10 20 02 00 07"));
        QVERIFY2(d.ok(), d.error.c_str());
        QVERIFY(!d.sample.euler_deg);
        QCOMPARE(d.unknownItems, std::size_t(1));
        QCOMPARE(*d.sample.packetCounter, std::uint16_t(7));
    }

    void freeAccelerationIsKeptApartFromAcceleration()
    {
        const MtData2Decoded onlyFree = decodeMtData2(bytes("40 30 0C 3E 80 00 00 BF 00 00 00 3F 80 00 00"));
        QVERIFY2(onlyFree.ok(), onlyFree.error.c_str());
        QVERIFY(!onlyFree.sample.acceleration);
        QCOMPARE(*onlyFree.sample.freeAcceleration, Eigen::Vector3d(0.25, -0.5, 1.0));

        MtData2Sample s;
        s.acceleration = Eigen::Vector3d(0.25, -0.5, 9.8125);
        s.freeAcceleration = Eigen::Vector3d(0.25, -0.5, 0.0);
        const MtData2Decoded both = decodeMtData2(encodeMtData2(s));
        QCOMPARE(*both.sample.acceleration, *s.acceleration);
        QCOMPARE(*both.sample.freeAcceleration, *s.freeAcceleration);
    }

    void baroPressureIsPascal()
    {
        const MtData2Decoded d = decodeMtData2(bytes("30 10 04 00 01 86 DE"));  // 100062 Pa (SCOT)
        QVERIFY2(d.ok(), d.error.c_str());
        QCOMPARE(*d.sample.pressure_pa, 100062.0);
    }

    void unknownIdentifiersAreSkippedBySize()
    {
        // LatLon fp16.32 (0x5042, 12 bytes) and a GnssPvtData-like item between known ones.
        QByteArray gnss = "70 10 5E" + QByteArray(94 * 2, 'A');
        const MtData2Decoded d = decodeMtData2(bytes("10 20 02 00 2A 50 42 0C 00 00 00 00 00 2D 00 00 00 00 00 08 " + gnss
                                                     + " 40 20 0C 3E 80 00 00 BF 00 00 00 41 1D 00 00"));
        QVERIFY2(d.ok(), d.error.c_str());
        QCOMPARE(d.unknownItems, std::size_t(2));
        QCOMPARE(*d.sample.packetCounter, std::uint16_t(42));
        QCOMPARE(*d.sample.acceleration, Eigen::Vector3d(0.25, -0.5, 9.8125));
    }

    void emptyPayloadCarriesNothing()
    {
        const MtData2Decoded d = decodeMtData2(nullptr, 0);
        QVERIFY(d.ok());
        QVERIFY(!d.sample.packetCounter);
        QVERIFY(!d.sample.acceleration);
    }

    void malformedPayloadsAreReported_data()
    {
        QTest::addColumn<QByteArray>("payload");
        QTest::addColumn<QString>("expected");
        QTest::newRow("item runs past the end") << QByteArray("10 20 02 04 D2 40 20 0C 3E 80 00 00")
                                                << "item 0x4020 at payload offset 5 claims 12 bytes but only 4 remain";
        QTest::newRow("unknown item runs past the end") << QByteArray("50 42 0C 00")
                                                        << "item 0x5042 at payload offset 0 claims 12 bytes";
        QTest::newRow("payload ends inside a header") << QByteArray("10 20 02 04 D2 40 20")
                                                      << "ends inside an item header at offset 5";
        QTest::newRow("known item with the wrong size") << QByteArray("10 20 04 00 00 04 D2")
                                                        << "item 0x1020 at payload offset 0 has 4 bytes, expected 2";
        QTest::newRow("real item sized for another precision") << QByteArray("40 22 0C 3E 80 00 00 BF 00 00 00 41 1D 00 00")
                                                               << "item 0x4022 at payload offset 0 has 12 bytes, expected 18";
    }
    void malformedPayloadsAreReported()
    {
        QFETCH(QByteArray, payload);
        QFETCH(QString, expected);
        const std::vector<std::uint8_t> data = bytes(payload);
        // An exact-size heap copy, so a sanitizer would catch any read past the end.
        const std::unique_ptr<std::uint8_t[]> exact(new std::uint8_t[data.size()]);
        std::copy(data.begin(), data.end(), exact.get());
        const MtData2Decoded d = decodeMtData2(exact.get(), data.size());
        QVERIFY(!d.ok());
        QVERIFY2(QString::fromStdString(d.error).contains(expected), d.error.c_str());
    }

    void itemsBeforeTheDamageAreKept()
    {
        const MtData2Decoded d = decodeMtData2(bytes("10 20 02 04 D2 40 20 0C 3E 80 00 00"));
        QVERIFY(!d.ok());
        QCOMPARE(*d.sample.packetCounter, std::uint16_t(1234));
        QVERIFY(!d.sample.acceleration);
    }
};

QTEST_APPLESS_MAIN(TestMtData2)
#include "tst_mtdata2.moc"
