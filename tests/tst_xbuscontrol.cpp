// The control messages of the init sequence: every builder produces the checksum-verified frame of
// docs/xbus.md section 8, the reply parsers read what devices send (both firmware
// revision layouts, 4- and 8-byte device ids, space-padded product codes) and reject malformed
// payloads in words, Error codes read as text, and baud codes map both ways.
#include "xbus/XbusControl.h"

#include "xbus/MtData2.h"

#include <QtTest>

using namespace footpath;

namespace {

QByteArray hexOf(const XbusMessage& message)
{
    const std::vector<std::uint8_t> frame = encodeFrame(message);
    return QByteArray(reinterpret_cast<const char*>(frame.data()), static_cast<int>(frame.size())).toHex(' ').toUpper();
}

std::vector<std::uint8_t> bytes(const QByteArray& hex)
{
    const QByteArray raw = QByteArray::fromHex(hex);
    return {raw.begin(), raw.end()};
}

/// Section 8.2 (MTD-EX, MTi-G-710): ten entries.
const QByteArray kMtdExConfiguration = "10 20 FF FF 10 60 FF FF 20 10 00 64 40 20 01 90 80 20 01 90 "
                                       "C0 20 00 64 E0 20 FF FF 50 42 00 64 50 22 00 64 D0 12 00 64";

}  // namespace

class TestXbusControl : public QObject {
    Q_OBJECT
private slots:
    void builtFramesMatchTheProtocolSheet_data()
    {
        QTest::addColumn<QByteArray>("frame");
        QTest::addColumn<QByteArray>("expected");
        const auto row = [](const char* name, const XbusMessage& message, const char* expected) {
            QTest::newRow(name) << hexOf(message) << QByteArray(expected);
        };
        row("GoToConfig", goToConfigMessage(), "FA FF 30 00 D1");
        row("GoToConfigAck", ackMessage(XbusMid::GoToConfig), "FA FF 31 00 D0");
        row("GoToMeasurement", goToMeasurementMessage(), "FA FF 10 00 F1");
        row("GoToMeasurementAck", ackMessage(XbusMid::GoToMeasurement), "FA FF 11 00 F0");
        row("WakeUp", wakeUpMessage(), "FA FF 3E 00 C3");
        row("WakeUpAck", wakeUpAckMessage(), "FA FF 3F 00 C2");
        row("Reset", resetMessage(), "FA FF 40 00 C1");
        row("ResetAck", ackMessage(XbusMid::Reset), "FA FF 41 00 C0");
        row("ReqDID", reqDeviceIdMessage(), "FA FF 00 00 01");
        row("DeviceID", deviceIdMessage(0x037003F8), "FA FF 01 04 03 70 03 F8 8E");
        row("ReqProductCode", reqProductCodeMessage(), "FA FF 1C 00 E5");
        row("ProductCode", productCodeMessage("MTi-300-2A5G4"),
            "FA FF 1D 0D 4D 54 69 2D 33 30 30 2D 32 41 35 47 34 BD");
        row("ReqFWRev", reqFirmwareRevMessage(), "FA FF 12 00 EF");
        row("FirmwareRev", firmwareRevMessage({1, 8, 2, std::nullopt, std::nullopt}), "FA FF 13 03 01 08 02 E0");
        row("ReqBaudrate", reqBaudrateMessage(), "FA FF 18 00 E9");
        row("BaudrateAck 115200", baudrateMessage(*xbusBaudCode(115200)), "FA FF 19 01 02 E5");
        row("SetBaudrate 921600", setBaudrateMessage(*xbusBaudCode(921600)), "FA FF 18 01 80 68");
        row("SetBaudrateAck", ackMessage(XbusMid::SetBaudrate), "FA FF 19 00 E8");
        row("SetBaudrate 115200", setBaudrateMessage(*xbusBaudCode(115200)), "FA FF 18 01 02 E6");
        row("ReqOutputConfiguration", reqOutputConfigurationMessage(), "FA FF C0 00 41");
        row("ReqConfiguration", xbusMessage(XbusMid::ReqConfiguration), "FA FF 0C 00 F5");
        row("Error 4", errorMessage(XbusErrorCode::InvalidMessage), "FA FF 42 01 04 BA");
        row("empty output configuration", *setOutputConfigurationMessage({{0x0000, 0}}), "FA FF C0 04 00 00 00 00 3D");
    }
    void builtFramesMatchTheProtocolSheet()
    {
        QFETCH(QByteArray, frame);
        QFETCH(QByteArray, expected);
        QCOMPARE(frame, expected);
    }

    void setOutputConfigurationOfTheMtdExample()  // section 8.2, request and echo
    {
        const auto parsed = parseOutputConfiguration(bytes(kMtdExConfiguration));
        QVERIFY2(parsed.ok(), parsed.error.c_str());
        QCOMPARE(parsed.value.size(), std::size_t(10));
        QCOMPARE(parsed.value[2].dataId, std::uint16_t(0x2010));
        QCOMPARE(parsed.value[3].rate_hz, std::uint16_t(400));
        QCOMPARE(hexOf(*setOutputConfigurationMessage(parsed.value)),
                 "FA FF C0 28 " + kMtdExConfiguration + " 73");
        QCOMPARE(hexOf(outputConfigurationMessage(parsed.value)), "FA FF C1 28 " + kMtdExConfiguration + " 72");
    }

    void setOutputConfigurationOfTheArduinoExample()  // section 8.2: Acc, RateOfTurn, MagneticField at 100 Hz
    {
        using namespace MtData2Id;
        const auto message = setOutputConfigurationMessage({{Acceleration, 100}, {RateOfTurn, 100}, {MagneticField, 100}});
        QCOMPARE(hexOf(*message), QByteArray("FA FF C0 0C 40 20 00 64 80 20 00 64 C0 20 00 64 29"));
    }

    void footpathAsksForCountersTimeAndEverySensor()
    {
        using namespace MtData2Id;
        const std::vector<OutputConfigEntry> entries = footpathOutputConfiguration(200);
        QCOMPARE(entries.size(), std::size_t(6));
        QCOMPARE(findOutputEntry(entries, PacketCounter)->rate_hz, OutputConfigEntry::kEveryMessage);
        QCOMPARE(findOutputEntry(entries, SampleTimeFine)->rate_hz, OutputConfigEntry::kEveryMessage);
        for (std::uint16_t id : {Acceleration, RateOfTurn, MagneticField, BaroPressure})
            QCOMPARE(findOutputEntry(entries, id)->rate_hz, std::uint16_t(200));
        QVERIFY(!findOutputEntry(entries, Quaternion));
        QCOMPARE(findOutputEntry(entries, std::uint16_t(Acceleration | 0x3))->dataId, Acceleration);  // precision ignored
        QCOMPARE(QString::fromStdString(describeOutputConfiguration({{PacketCounter, 0xFFFF}, {Acceleration, 100}})),
                 QStringLiteral("PacketCounter (every message), Acceleration 100 Hz"));
    }

    void outputConfigurationLimits()
    {
        QVERIFY(!setOutputConfigurationMessage({}));  // LEN 0 would be the request, not a set
        QVERIFY(!setOutputConfigurationMessage(std::vector<OutputConfigEntry>(33, {0x4020, 100})));
        QVERIFY(setOutputConfigurationMessage(std::vector<OutputConfigEntry>(32, {0x4020, 100})));
        const auto odd = parseOutputConfiguration(bytes("40 20 00"));
        QVERIFY(!odd.ok());
        QVERIFY(odd.error.find("multiple of 4") != std::string::npos);
        const auto many = parseOutputConfiguration(std::vector<std::uint8_t>(33 * 4, 0));
        QVERIFY(many.error.find("at most 32") != std::string::npos);
    }

    void deviceIdReplies()
    {
        QCOMPARE(parseDeviceId(bytes("03 70 03 F8")).value, std::uint64_t(0x037003F8));
        QCOMPARE(parseDeviceId(bytes("00 00 00 01 23 45 67 89")).value, std::uint64_t(0x0123456789));
        QCOMPARE(QString::fromStdString(formatDeviceId(0x037003F8)), QStringLiteral("037003F8"));
        QCOMPARE(QString::fromStdString(formatDeviceId(0x0123456789)), QStringLiteral("0000000123456789"));
        QCOMPARE(hexOf(deviceIdMessage(0x0123456789)), QByteArray("FA FF 01 08 00 00 00 01 23 45 67 89 9F"));
        const auto bad = parseDeviceId(bytes("03 70 03"));
        QVERIFY(!bad.ok());
        QCOMPARE(QString::fromStdString(bad.error), QStringLiteral("DeviceID has 3 bytes, expected 4 or 8"));
    }

    void productCodeReplies()
    {
        QCOMPARE(parseProductCode(bytes("4D 54 69 2D 33 30 30 2D 32 41 35 47 34")).value, std::string("MTi-300-2A5G4"));
        // Space-padded to 20 bytes, cut at the first space as XSP does.
        QCOMPARE(parseProductCode(bytes("4D 54 69 2D 36 33 30 20 20 20 20 20 20 20 20 20 20 20 20 20")).value,
                 std::string("MTi-630"));
        QVERIFY(!parseProductCode(bytes("20 20")).ok());
        QVERIFY(parseProductCode(bytes("4D 54 FF")).error.find("non-ASCII") != std::string::npos);
        QCOMPARE(productCodeMessage(std::string(25, 'X')).payload.size(), std::size_t(20));
    }

    void firmwareRevisionReplies()
    {
        const auto old = parseFirmwareRevision(bytes("01 08 02"));
        QVERIFY(old.ok());
        QCOMPARE(QString::fromStdString(old.value.toString()), QStringLiteral("1.8.2"));
        // SCOT's 11-byte form: 1.8.2 build 37 rev 70964.
        const auto current = parseFirmwareRevision(bytes("01 08 02 00 00 00 25 00 01 15 34"));
        QVERIFY(current.ok());
        QCOMPARE(QString::fromStdString(current.value.toString()), QStringLiteral("1.8.2 build 37 rev 70964"));
        QCOMPARE(firmwareRevMessage(current.value).payload, bytes("01 08 02 00 00 00 25 00 01 15 34"));
        QVERIFY(parseFirmwareRevision(bytes("01 08")).error.find("expected 3 or 11") != std::string::npos);
    }

    void baudCodes()
    {
        for (std::uint32_t baud : {460800u, 230400u, 115200u, 76800u, 57600u, 38400u, 28800u, 19200u, 14400u, 9600u,
                                   921600u, 4800u, 2000000u})
            QCOMPARE(*xbusBaudFromCode(*xbusBaudCode(baud)), baud);
        QCOMPARE(*xbusBaudCode(921600), std::uint8_t(0x80));  // the legacy code XSP sends
        QCOMPARE(*xbusBaudFromCode(0x0A), std::uint32_t(921600));
        QVERIFY(!xbusBaudCode(4000000));  // 0x0D is 3.6864 or 4 Mbaud depending on the source
        QVERIFY(!xbusBaudFromCode(0xFF));
        QCOMPARE(parseBaudCode(bytes("02")).value, std::uint8_t(0x02));
        QVERIFY(!parseBaudCode({}).ok());
        QCOMPARE(xbusProbeBaudRates().front(), std::uint32_t(115200));
        QCOMPARE(xbusProbeBaudRates().size(), std::size_t(9));
    }

    void errorCodesReadAsText_data()
    {
        QTest::addColumn<int>("code");
        QTest::addColumn<QString>("text");
        QTest::newRow("invalid message") << 4 << "message invalid or not implemented (error 4)";
        QTest::newRow("invalid period") << 3 << "invalid period (error 3)";
        QTest::newRow("baud") << 0x20 << "baud rate not in the valid range (error 32)";
        QTest::newRow("parameter") << 0x21 << "invalid parameter (error 33)";
        QTest::newRow("overflow") << 0x29 << "data overflow: more data than the link can carry (baud rate too low) (error 41)";
        QTest::newRow("output config") << 0x35 << "output configuration error: cannot go to measurement (error 53)";
        QTest::newRow("unknown") << 200 << "unknown device error (error 200)";
    }
    void errorCodesReadAsText()
    {
        QFETCH(int, code);
        QFETCH(QString, text);
        QCOMPARE(QString::fromStdString(xbusErrorText(static_cast<std::uint8_t>(code))), text);
        QCOMPARE(QString::fromStdString(xbusErrorText(errorMessage(static_cast<std::uint8_t>(code)).payload)), text);
    }
    void errorWithoutCode()
    {
        QCOMPARE(QString::fromStdString(xbusErrorText(std::vector<std::uint8_t>{})),
                 QStringLiteral("Error message without a code"));
    }

    void midNames()
    {
        QCOMPARE(QString::fromStdString(xbusMidName(XbusMid::GoToConfig)), QStringLiteral("GoToConfig"));
        QCOMPARE(QString::fromStdString(xbusMidName(XbusMid::ReqDid)), QStringLiteral("ReqDID"));
        QCOMPARE(QString::fromStdString(xbusMidName(0x5A)), QStringLiteral("MID 0x5A"));
        QCOMPARE(xbusReplyMid(XbusMid::ReqFwRev), XbusMid::FirmwareRev);
        QCOMPARE(xbusReplyMid(XbusMid::SetOutputConfiguration), XbusMid::OutputConfiguration);
    }

    void configurationForLogs()
    {
        const FirmwareRevision firmware{1, 8, 2, std::nullopt, std::nullopt};
        const XbusConfiguration at100 = mtData2Configuration(0x037003F8, 100, firmware);
        QCOMPARE(at100.samplingPeriod, std::uint16_t(1152));
        QCOMPARE(at100.outputRate_hz(), 100.0);
        QCOMPARE(at100.devices.size(), std::size_t(1));
        QCOMPARE(at100.devices.front().deviceId, std::uint32_t(0x037003F8));
        QCOMPARE(at100.devices.front().firmware[1], std::uint8_t(8));
        // 115200 / 2000 is not whole: no period rather than a wrong one.
        QCOMPARE(mtData2Configuration(0x037003F8, 2000, firmware).samplingPeriod, std::uint16_t(0));
        const auto parsed = parseConfiguration(encodeConfiguration(at100));
        QVERIFY2(parsed.ok(), parsed.error.c_str());
        QCOMPARE(parsed.configuration.masterDeviceId, std::uint32_t(0x037003F8));
    }
};

QTEST_APPLESS_MAIN(TestXbusControl)
#include "tst_xbuscontrol.moc"
