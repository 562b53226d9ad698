// Legacy devices: the Configuration message of docs/xbus.md section 8.8 and the MTData
// examples of section 8.7 decode to their documented values; layouts size and decode every block
// in the order of section 6.3; every data format round-trips.
#include "xbus/LegacyMtData.h"

#include <QtTest>

#include <cmath>

using namespace footpath;
namespace Mode = LegacyOutputMode;
namespace Settings = LegacyOutputSettings;

namespace {

std::vector<std::uint8_t> bytes(const QByteArray& hex)
{
    const QByteArray raw = QByteArray::fromHex(hex);
    return {raw.begin(), raw.end()};
}

/// Section 8.8: SCOT's MTi-300 Configuration payload, 118 bytes.
std::vector<std::uint8_t> scotConfiguration()
{
    std::vector<std::uint8_t> payload = bytes("03 70 03 F8 04 80 00 00");
    payload.resize(payload.size() + 88, 0);
    const std::vector<std::uint8_t> tail = bytes("00 01 03 70 03 F8 00 00 00 00 00 00 00 01 00 27 01 08 02 49 05 01");
    payload.insert(payload.end(), tail.begin(), tail.end());
    return payload;
}

LegacyDataLayout layout(std::uint16_t mode, std::uint32_t settings)
{
    LegacyDataLayout result;
    result.outputMode = mode;
    result.outputSettings = settings;
    return result;
}

bool near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tolerance)
{
    return (actual - expected).cwiseAbs().maxCoeff() <= tolerance;
}

}  // namespace

class TestLegacyMtData : public QObject {
    Q_OBJECT
private slots:
    void defaultOrientationMessage()  // section 8.7, first example
    {
        const LegacyDataLayout defaults;
        QCOMPARE(defaults.payloadSize(), std::size_t(18));
        const MtData2Decoded d = decodeLegacyMtData(bytes("3F 80 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 2A"), defaults);
        QVERIFY2(d.ok(), d.error.c_str());
        QCOMPARE(d.sample.quaternion->w(), 1.0);
        QCOMPARE(d.sample.quaternion->vec(), Eigen::Vector3d(0, 0, 0));
        QCOMPARE(*d.sample.packetCounter, std::uint16_t(42));
        QCOMPARE(d.sample.orientationFrame, XdaCoordinateFrame::Nwu);  // legacy X north, Z up
        QVERIFY(!d.sample.acceleration);
    }

    void calibratedMessage()  // section 8.7, second example
    {
        const LegacyDataLayout calibrated = layout(Mode::Calibrated, Settings::TimestampSampleCounter);
        QCOMPARE(calibrated.payloadSize(), std::size_t(38));
        const MtData2Decoded d = decodeLegacyMtData(bytes("3E 80 00 00 BF 00 00 00 41 1D 00 00 3C 80 00 00 BD 00 00 00 "
                                                          "00 00 00 00 3F 00 00 00 BE 80 00 00 3F 80 00 00 00 2A"),
                                                    calibrated);
        QVERIFY2(d.ok(), d.error.c_str());
        QCOMPARE(*d.sample.acceleration, Eigen::Vector3d(0.25, -0.5, 9.8125));
        QCOMPARE(*d.sample.rateOfTurn, Eigen::Vector3d(0.015625, -0.03125, 0.0));
        QCOMPARE(*d.sample.magneticField, Eigen::Vector3d(0.5, -0.25, 1.0));
        QCOMPARE(*d.sample.packetCounter, std::uint16_t(42));
        QVERIFY(!d.sample.quaternion);
    }

    void blocksAreReadInDocumentedOrder()
    {
        // GPS PVT (skipped), calibrated without mag, auxiliary (skipped), status, sample counter,
        // built by hand so that the encoder does not check itself.
        const LegacyDataLayout withExtras = layout(Mode::GpsPvt | Mode::Calibrated | Mode::Auxiliary | Mode::Status,
                                                   Settings::TimestampSampleCounter | Settings::DisableMag);
        const std::vector<std::uint8_t> payload = bytes(QByteArray(88, 'E') + " 3E 80 00 00 BF 00 00 00 41 1D 00 00 "
                                                        "3C 80 00 00 BD 00 00 00 00 00 00 00 AA AA BB BB 03 01 02");
        QCOMPARE(withExtras.payloadSize(), payload.size());
        const MtData2Decoded d = decodeLegacyMtData(payload, withExtras);
        QVERIFY2(d.ok(), d.error.c_str());
        QCOMPARE(*d.sample.acceleration, Eigen::Vector3d(0.25, -0.5, 9.8125));
        QCOMPARE(*d.sample.rateOfTurn, Eigen::Vector3d(0.015625, -0.03125, 0.0));
        QVERIFY(!d.sample.magneticField);
        QCOMPARE(*d.sample.statusByte, std::uint8_t(3));
        QCOMPARE(*d.sample.packetCounter, std::uint16_t(0x0102));
    }

    void payloadSizes_data()
    {
        QTest::addColumn<int>("mode");
        QTest::addColumn<int>("settings");
        QTest::addColumn<int>("size");
        QTest::newRow("nothing") << 0 << 0 << 0;
        QTest::newRow("temperature, calibrated, Euler, counter") << 0x0007 << 0x0005 << 4 + 36 + 12 + 2;
        QTest::newRow("calibrated + quaternion in fp16.32") << 0x0006 << 0x0201 << 54 + 24 + 2;
        QTest::newRow("matrix in float64") << 0x0004 << 0x0308 << 72;
        QTest::newRow("calibrated without acc and mag") << 0x0002 << 0x0050 << 12;
        QTest::newRow("raw + counter") << 0x4000 << 0x0001 << 22;
        QTest::newRow("status + UTC") << 0x0800 << 0x0002 << 13;
        QTest::newRow("auxiliary without AIN2") << 0x0008 << 0x0800 << 2;
        QTest::newRow("position + velocity in fp12.20") << 0x0030 << 0x0100 << 24;
        QTest::newRow("GPS PVT") << 0x1000 << 0x0000 << 44;
    }
    void payloadSizes()
    {
        QFETCH(int, mode);
        QFETCH(int, settings);
        QFETCH(int, size);
        const LegacyDataLayout l = layout(std::uint16_t(mode), std::uint32_t(settings));
        QVERIFY2(l.validate().empty(), l.validate().c_str());
        QCOMPARE(int(l.payloadSize()), size);
        QCOMPARE(int(encodeLegacyMtData(MtData2Sample{}, l).size()), size);
    }

    void everyFormatRoundTrips_data()
    {
        QTest::addColumn<int>("format");
        QTest::addColumn<int>("orientation");
        QTest::addColumn<double>("tolerance");
        QTest::newRow("float32 quaternion") << 0x000 << 0x0 << 1e-6;
        QTest::newRow("fp12.20 Euler") << 0x100 << 0x4 << 1e-6;
        QTest::newRow("fp16.32 quaternion") << 0x200 << 0x0 << 1e-9;
        QTest::newRow("float64 Euler") << 0x300 << 0x4 << 0.0;
    }
    void everyFormatRoundTrips()
    {
        QFETCH(int, format);
        QFETCH(int, orientation);
        QFETCH(double, tolerance);
        const LegacyDataLayout l = layout(Mode::Temperature | Mode::Calibrated | Mode::Orientation | Mode::Status,
                                          Settings::TimestampSampleCounter | Settings::Ned | std::uint32_t(format)
                                              | std::uint32_t(orientation));
        MtData2Sample in;
        in.temperature_degC = 31.7;
        in.acceleration = Eigen::Vector3d(0.1, -0.2, 9.81);
        in.rateOfTurn = Eigen::Vector3d(1.1, -2.2, 0.003);
        in.magneticField = Eigen::Vector3d(0.3, 0.4, -0.5);
        in.quaternion = Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5);
        in.euler_deg = Eigen::Vector3d(10.5, -20.25, 179.0);
        in.statusByte = 0x07;
        in.packetCounter = 65000;
        const std::vector<std::uint8_t> payload = encodeLegacyMtData(in, l);
        QCOMPARE(payload.size(), l.payloadSize());
        const MtData2Decoded d = decodeLegacyMtData(payload, l);
        QVERIFY2(d.ok(), d.error.c_str());
        const double scaled = tolerance * 200.0;  // the largest values are near 180
        QVERIFY(std::abs(*d.sample.temperature_degC - 31.7) <= scaled);
        QVERIFY(near(*d.sample.acceleration, *in.acceleration, scaled));
        QVERIFY(near(*d.sample.rateOfTurn, *in.rateOfTurn, scaled));
        QVERIFY(near(*d.sample.magneticField, *in.magneticField, scaled));
        if (orientation == 0) {
            QVERIFY((d.sample.quaternion->coeffs() - in.quaternion->coeffs()).cwiseAbs().maxCoeff() <= scaled);
            QVERIFY(!d.sample.euler_deg);
        } else {
            QVERIFY(near(*d.sample.euler_deg, *in.euler_deg, scaled));
            QVERIFY(!d.sample.quaternion);
        }
        QCOMPARE(d.sample.orientationFrame, XdaCoordinateFrame::Ned);
        QCOMPARE(*d.sample.statusByte, std::uint8_t(0x07));
        QCOMPARE(*d.sample.packetCounter, std::uint16_t(65000));
    }

    void wrongLengthIsAnError()
    {
        const LegacyDataLayout calibrated = layout(Mode::Calibrated, Settings::TimestampSampleCounter);
        const MtData2Decoded d = decodeLegacyMtData(bytes("3F 80 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 2A"), calibrated);
        QVERIFY(!d.ok());
        QVERIFY2(QString::fromStdString(d.error).contains("has 18 bytes"), d.error.c_str());
        QVERIFY2(QString::fromStdString(d.error).contains("gives 38"), d.error.c_str());
    }

    void impossibleLayoutsAreRejected_data()
    {
        QTest::addColumn<int>("mode");
        QTest::addColumn<int>("settings");
        QTest::addColumn<QString>("expected");
        QTest::newRow("timestamp 3") << 0x0002 << 0x0003 << "undefined timestamp";
        QTest::newRow("orientation 0xC") << 0x0004 << 0x000C << "undefined orientation format";
        QTest::newRow("raw with calibrated") << 0x4002 << 0x0000 << "combines raw";
    }
    void impossibleLayoutsAreRejected()
    {
        QFETCH(int, mode);
        QFETCH(int, settings);
        QFETCH(QString, expected);
        const LegacyDataLayout l = layout(std::uint16_t(mode), std::uint32_t(settings));
        QVERIFY2(QString::fromStdString(l.validate()).contains(expected), l.validate().c_str());
        const std::vector<std::uint8_t> payload(l.payloadSize(), 0);
        QVERIFY(!decodeLegacyMtData(payload, l).ok());
    }

    void configurationMessage()  // section 8.8
    {
        const std::vector<std::uint8_t> payload = scotConfiguration();
        const XbusConfigurationParsed parsed = parseConfiguration(payload);
        QVERIFY2(parsed.ok(), parsed.error.c_str());
        const XbusConfiguration& c = parsed.configuration;
        QCOMPARE(c.masterDeviceId, std::uint32_t(0x037003F8));
        QCOMPARE(c.samplingPeriod, std::uint16_t(1152));
        QCOMPARE(c.outputSkipFactor, std::uint16_t(0));
        QCOMPARE(c.outputRate_hz(), 100.0);
        QCOMPARE(c.devices.size(), std::size_t(1));
        const XbusConfiguration::Device& device = c.devices[0];
        QCOMPARE(device.deviceId, std::uint32_t(0x037003F8));
        QCOMPARE(device.dataLength, std::uint16_t(0));
        QCOMPARE(device.layout.outputMode, std::uint16_t(0));
        QCOMPARE(device.layout.outputSettings, std::uint32_t(1));
        QCOMPARE(device.filterProfile, std::uint16_t(0x27));  // "general"
        QCOMPARE(int(device.firmware[0]), 1);
        QCOMPARE(int(device.firmware[1]), 8);
        QCOMPARE(int(device.firmware[2]), 2);
        QCOMPARE(device.filterType, 'I');
        QCOMPARE(int(device.filterVersion[0]), 5);
        QCOMPARE(int(device.filterVersion[1]), 1);
        QCOMPARE(encodeConfiguration(c), payload);
    }

    void configurationDateAndTimeRoundTrip()
    {
        XbusConfiguration c;
        c.samplingPeriod = 576;
        c.outputSkipFactor = 1;
        c.date = "20240620";
        c.time = "16343200";
        c.devices.resize(2);
        c.devices[1].layout = layout(Mode::Calibrated, Settings::TimestampSampleCounter);
        const std::vector<std::uint8_t> payload = encodeConfiguration(c);
        QCOMPARE(payload.size(), std::size_t(98 + 2 * 20));
        const XbusConfigurationParsed parsed = parseConfiguration(payload);
        QVERIFY2(parsed.ok(), parsed.error.c_str());
        QCOMPARE(parsed.configuration.date, std::string("20240620"));
        QCOMPARE(parsed.configuration.time, std::string("16343200"));
        QCOMPARE(parsed.configuration.outputRate_hz(), 100.0);  // 115200 / (576 * 2)
        QCOMPARE(parsed.configuration.devices[1].layout.outputMode, Mode::Calibrated);
    }

    void outputRate_data()
    {
        QTest::addColumn<int>("period");
        QTest::addColumn<int>("skip");
        QTest::addColumn<double>("rate");
        QTest::newRow("default 1152") << 1152 << 0 << 100.0;
        QTest::newRow("400 Hz") << 288 << 0 << 400.0;
        QTest::newRow("minimum period 225") << 225 << 0 << 512.0;
        QTest::newRow("skip 3") << 1152 << 3 << 25.0;
        QTest::newRow("only on request") << 1152 << 0xFFFF << 0.0;
        QTest::newRow("no period") << 0 << 0 << 0.0;
    }
    void outputRate()
    {
        QFETCH(int, period);
        QFETCH(int, skip);
        QFETCH(double, rate);
        XbusConfiguration c;
        c.samplingPeriod = std::uint16_t(period);
        c.outputSkipFactor = std::uint16_t(skip);
        QCOMPARE(c.outputRate_hz(), rate);
    }

    void malformedConfigurationsAreReported_data()
    {
        QTest::addColumn<int>("size");
        QTest::addColumn<int>("deviceCount");
        QTest::addColumn<QString>("expected");
        QTest::newRow("too short") << 50 << 0 << "has 50 bytes, at least 98 expected";
        QTest::newRow("count says two, one present") << 118 << 2 << "announces 2 device(s), which take 138";
        QTest::newRow("count says none, one present") << 118 << 0 << "announces 0 device(s), which take 98";
    }
    void malformedConfigurationsAreReported()
    {
        QFETCH(int, size);
        QFETCH(int, deviceCount);
        QFETCH(QString, expected);
        std::vector<std::uint8_t> payload = scotConfiguration();
        payload.resize(std::size_t(size));
        if (payload.size() >= 98)
            payload[97] = std::uint8_t(deviceCount);
        const XbusConfigurationParsed parsed = parseConfiguration(payload);
        QVERIFY(!parsed.ok());
        QVERIFY2(QString::fromStdString(parsed.error).contains(expected), parsed.error.c_str());
    }
};

QTEST_APPLESS_MAIN(TestLegacyMtData)
#include "tst_legacymtdata.moc"
