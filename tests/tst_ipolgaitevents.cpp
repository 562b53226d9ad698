// Gait events of the IPOL MTw dataset (core/io/IpolGaitEvents.h): the real sidecar JSONs with the
// swings of each foot, the warning when the time base has gaps, events beyond the recording, and
// sidecars that are malformed or lack keys.

#include "io/IpolGaitEvents.h"
#include "io/XsensTextReader.h"

#include "TestData.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

using footpath::Recording;
using footpath::SampleRange;

namespace {

footpath::ImportResult readExport(const QString& path)
{
    std::ifstream in(path.toStdString(), std::ios::binary | std::ios::ate);
    const auto size = static_cast<std::size_t>(std::max<std::streamoff>(0, in.tellg()));
    in.seekg(0);
    return footpath::readXsensText(in, path.toStdString(), {}, size);
}

/// `count` samples 0.01 s apart, with `gapAfter` (if not 0) followed by 5 lost packets.
Recording uniformRecording(std::size_t count, std::size_t gapAfter = 0)
{
    Recording recording;
    recording.samples.resize(count);
    double time_s = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        recording.samples[i].time_s = time_s;
        time_s += (gapAfter != 0 && i == gapAfter) ? 0.06 : 0.01;
    }
    return recording;
}

bool writeFile(const QString& path, const QByteArray& content)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(content) == content.size();
}

QString joined(const std::vector<std::string>& lines)
{
    QStringList list;
    for (const std::string& line : lines)
        list << QString::fromStdString(line);
    return list.join('\n');
}

const QByteArray kValidSidecar = R"({"Subject": 9, "Height": NaN, "TrialBoundaries": [10, 80],
    "UTurnBoundaries": [40, 50], "LeftFootEvents": [[20, 30], [12, 15]], "RightFootEvents": [[35, 45]]})";

}  // namespace

class TestIpolGaitEvents : public QObject {
    Q_OBJECT

private slots:
    void realSidecars_data();
    void realSidecars();
    void eachFootTakesItsOwnEvents_data();
    void eachFootTakesItsOwnEvents();
    void gapsInTheTimeBaseWarn();
    void eventsBeyondTheRecordingAreDropped();
    void otherFilesAreLeftAlone_data();
    void otherFilesAreLeftAlone();
    void malformedSidecars_data();
    void malformedSidecars();
};

void TestIpolGaitEvents::realSidecars_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("json");
    QTest::addColumn<int>("swings");
    QTest::addColumn<int>("firstToeOff");
    QTest::addColumn<int>("lastHeelStrike");
    QTest::addColumn<int>("trialFirst");
    QTest::addColumn<int>("trialLast");
    QTest::addColumn<QStringList>("warningFragments");

    // Counted in the JSON files (python3 json.load: len of LeftFootEvents / RightFootEvents) and
    // checked against each export's row count (see tst_xsenstextreader). 12-3 lists swings after
    // its TrialBoundaries end (2049), some beyond the end of the export: left 19 pairs, the last two
    // start at 2553 and 2724 > 2470 (2471 rows) -> 17 kept; right 19 pairs, the last ends at 2869 >
    // 2732 -> 18 kept, two more (2455-2501, 2635-2680) outside the trial. 10-1 and 14-1 write
    // Height and Weight as NaN, which strict JSON rejects. Gap warnings follow the time base of each
    // foot: 3-2_lf has no gap although 3-2_rf has 25.
    const QString gap = QStringLiteral("gap(s) from lost packets");
    QTest::newRow("1-1 left") << "1-1_lf.txt" << "1-1.json" << 17 << 527 << 2417 << 459 << 2464 << QStringList{gap};
    QTest::newRow("1-1 right") << "1-1_rf.txt" << "1-1.json" << 18 << 459 << 2464 << 459 << 2464 << QStringList{gap};
    QTest::newRow("1-4 left") << "1-4_lf.txt" << "1-4.json" << 17 << 599 << 2513 << 536 << 2580 << QStringList{};
    QTest::newRow("1-4 right") << "1-4_rf.txt" << "1-4.json" << 18 << 536 << 2580 << 536 << 2580 << QStringList{};
    QTest::newRow("10-1 left") << "10-1_lf.txt" << "10-1.json" << 17 << 432 << 2137 << 432 << 2137 << QStringList{};
    QTest::newRow("10-1 right") << "10-1_rf.txt" << "10-1.json" << 16 << 493 << 2093 << 432 << 2137 << QStringList{};
    QTest::newRow("12-3 left") << "12-3_lf.txt" << "12-3.json" << 17 << 329 << 2049 << 329 << 2049
                               << QStringList{"2 left foot swing(s) in 12-3.json end beyond the recording's 2471 samples",
                                              gap};
    QTest::newRow("12-3 right") << "12-3_rf.txt" << "12-3.json" << 18 << 386 << 2680 << 329 << 2049
                                << QStringList{"1 right foot swing(s) in 12-3.json end beyond the recording's 2733 samples",
                                               "2 right foot swing(s) in 12-3.json lie outside its TrialBoundaries 329-2049",
                                               gap};
    QTest::newRow("14-1 left") << "14-1_lf.txt" << "14-1.json" << 15 << 505 << 2137 << 436 << 2181 << QStringList{};
    QTest::newRow("14-1 right") << "14-1_rf.txt" << "14-1.json" << 16 << 436 << 2181 << 436 << 2181 << QStringList{};
    QTest::newRow("3-2 left") << "3-2_lf.txt" << "3-2.json" << 19 << 627 << 2898 << 559 << 2954 << QStringList{};
    QTest::newRow("3-2 right") << "3-2_rf.txt" << "3-2.json" << 20 << 559 << 2954 << 559 << 2954 << QStringList{gap};
}

void TestIpolGaitEvents::realSidecars()
{
    FOOTPATH_REQUIRE_DATASETS();
    QFETCH(QString, file);
    QFETCH(QString, json);
    QFETCH(int, swings);
    QFETCH(int, firstToeOff);
    QFETCH(int, lastHeelStrike);
    QFETCH(int, trialFirst);
    QFETCH(int, trialLast);
    QFETCH(QStringList, warningFragments);

    const QString path = datasetPath(QStringLiteral("xsens-mtw-ipol/") + file);
    footpath::ImportResult imported = readExport(path);
    QVERIFY2(imported.ok(), imported.error ? imported.error->text().c_str() : "");
    Recording& recording = imported.recording;
    std::vector<std::string> warnings;

    QVERIFY2(footpath::attachIpolGaitEvents(path.toStdString(), recording, warnings), qPrintable(joined(warnings)));
    const footpath::Reference& reference = recording.reference;
    QCOMPARE(int(reference.swings.size()), swings);
    QCOMPARE(int(reference.swings.front().first), firstToeOff);
    QCOMPARE(int(reference.swings.back().last), lastHeelStrike);
    QVERIFY(reference.hasTrialBoundaries);
    QCOMPARE(int(reference.trialBoundaries.first), trialFirst);
    QCOMPARE(int(reference.trialBoundaries.last), trialLast);
    for (const SampleRange& swing : reference.swings)
        QVERIFY(swing.first <= swing.last && swing.last < recording.samples.size());
    QCOMPARE(reference.notes.size(), std::size_t(2));
    QVERIFY2(reference.notes.front().rfind("gait events from " + json.toStdString(), 0) == 0, reference.notes.front().c_str());
    // The U-turn makes it the protocol's out-and-back walk: closed, 20 m (no closure or distance
    // error was reported for these files before).
    QVERIFY(reference.closedLoop);
    QCOMPARE(reference.knownLength_m, 20.0);
    QVERIFY2(reference.notes.back().rfind("closed walk of 20 m (UTurnBoundaries in " + json.toStdString(), 0) == 0,
             reference.notes.back().c_str());

    QCOMPARE(int(warnings.size()), int(warningFragments.size()));
    const QString all = joined(warnings);
    for (const QString& fragment : warningFragments)
        QVERIFY2(all.contains(fragment), qPrintable(all));
}

void TestIpolGaitEvents::eachFootTakesItsOwnEvents_data()
{
    QTest::addColumn<QString>("recordingName");
    QTest::addColumn<int>("swings");
    QTest::addColumn<int>("firstToeOff");
    QTest::addColumn<QString>("noteFragment");

    // The left list is out of order in the file: it comes back sorted by toe-off.
    QTest::newRow("left") << "9-9_lf.txt" << 2 << 12 << "left foot: 2 swing(s), trial samples 10-80";
    QTest::newRow("right") << "9-9_rf.txt" << 1 << 35 << "right foot: 1 swing(s), trial samples 10-80";
    QTest::newRow("upper-case suffix") << "9-9_LF.TXT" << 2 << 12 << "left foot";
}

void TestIpolGaitEvents::eachFootTakesItsOwnEvents()
{
    QFETCH(QString, recordingName);
    QFETCH(int, swings);
    QFETCH(int, firstToeOff);
    QFETCH(QString, noteFragment);

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(writeFile(dir.filePath("9-9.json"), kValidSidecar));
    Recording recording = uniformRecording(100);
    std::vector<std::string> warnings;

    QVERIFY(footpath::attachIpolGaitEvents(dir.filePath(recordingName).toStdString(), recording, warnings));
    QVERIFY2(warnings.empty(), qPrintable(joined(warnings)));
    QCOMPARE(int(recording.reference.swings.size()), swings);
    QCOMPARE(int(recording.reference.swings.front().first), firstToeOff);
    QVERIFY(std::is_sorted(recording.reference.swings.begin(), recording.reference.swings.end(),
                           [](const SampleRange& a, const SampleRange& b) { return a.first < b.first; }));
    QCOMPARE(recording.reference.notes.size(), std::size_t(2));  // the events, and the out-and-back walk
    QVERIFY2(QString::fromStdString(recording.reference.notes.front()).contains(noteFragment),
             recording.reference.notes.front().c_str());
}

void TestIpolGaitEvents::gapsInTheTimeBaseWarn()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(writeFile(dir.filePath("9-9.json"), kValidSidecar));
    const std::string path = dir.filePath("9-9_lf.txt").toStdString();

    Recording gapFree = uniformRecording(100);
    std::vector<std::string> noWarnings;
    QVERIFY(footpath::attachIpolGaitEvents(path, gapFree, noWarnings));
    QVERIFY2(noWarnings.empty(), qPrintable(joined(noWarnings)));

    Recording gapped = uniformRecording(100, 50);
    std::vector<std::string> warnings;
    QVERIFY(footpath::attachIpolGaitEvents(path, gapped, warnings));
    QCOMPARE(gapped.reference.swings.size(), std::size_t(2));  // attached all the same
    QCOMPARE(warnings.size(), std::size_t(1));
    QVERIFY2(QString::fromStdString(warnings.front()).contains("has 1 gap(s)")
                 && QString::fromStdString(warnings.front()).contains("do not line up"),
             warnings.front().c_str());
}

void TestIpolGaitEvents::eventsBeyondTheRecordingAreDropped()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(writeFile(dir.filePath("9-9.json"), kValidSidecar));
    Recording shortRecording = uniformRecording(25);  // indices 0..24: [12, 15] fits, [20, 30] does not
    std::vector<std::string> warnings;

    QVERIFY(footpath::attachIpolGaitEvents(dir.filePath("9-9_lf.txt").toStdString(), shortRecording, warnings));
    QCOMPARE(shortRecording.reference.swings.size(), std::size_t(1));
    QCOMPARE(int(shortRecording.reference.swings.front().last), 15);
    QVERIFY(!shortRecording.reference.hasTrialBoundaries);
    const QString all = joined(warnings);
    QCOMPARE(warnings.size(), std::size_t(2));
    QVERIFY2(all.contains("1 left foot swing(s) in 9-9.json end beyond the recording's 25 samples"), qPrintable(all));
    QVERIFY2(all.contains("TrialBoundaries 10-80 in 9-9.json end beyond"), qPrintable(all));
}

void TestIpolGaitEvents::otherFilesAreLeftAlone_data()
{
    QTest::addColumn<QString>("recordingName");
    QTest::addColumn<bool>("writeSidecar");

    QTest::newRow("no sidecar beside the export") << "9-9_lf.txt" << false;
    QTest::newRow("not a foot file") << "9-9.txt" << true;
    QTest::newRow("other suffix") << "9-9_lf.csv" << true;
    QTest::newRow("bare suffix") << "_lf" << true;
}

void TestIpolGaitEvents::otherFilesAreLeftAlone()
{
    QFETCH(QString, recordingName);
    QFETCH(bool, writeSidecar);

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    if (writeSidecar)
        QVERIFY(writeFile(dir.filePath("9-9.json"), kValidSidecar));
    Recording recording = uniformRecording(100);
    std::vector<std::string> warnings;

    QVERIFY(!footpath::attachIpolGaitEvents(dir.filePath(recordingName).toStdString(), recording, warnings));
    QVERIFY2(warnings.empty(), qPrintable(joined(warnings)));
    QVERIFY(recording.reference.swings.empty() && recording.reference.notes.empty());
    QVERIFY(!recording.reference.hasTrialBoundaries);
}

void TestIpolGaitEvents::malformedSidecars_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("fragment");

    QTest::newRow("empty file") << QByteArray() << "9-9.json is not valid JSON";
    QTest::newRow("cut off") << QByteArray(R"({"TrialBoundaries": [10, 80], "LeftFootEv)") << "9-9.json is not valid JSON";
    QTest::newRow("an array") << QByteArray("[[1, 2]]") << "9-9.json does not hold a JSON object";
    QTest::newRow("no LeftFootEvents") << QByteArray(R"({"TrialBoundaries": [10, 80], "RightFootEvents": []})")
                                       << "9-9.json: missing LeftFootEvents";
    QTest::newRow("no TrialBoundaries") << QByteArray(R"({"LeftFootEvents": [[20, 30]]})")
                                        << "9-9.json: missing TrialBoundaries";
    QTest::newRow("neither") << QByteArray(R"({"Subject": 9})")
                             << "9-9.json: missing TrialBoundaries; missing LeftFootEvents";
    QTest::newRow("TrialBoundaries not a pair") << QByteArray(R"({"TrialBoundaries": [10], "LeftFootEvents": []})")
                                                << "TrialBoundaries is not a pair of sample indices";
    QTest::newRow("events not a list") << QByteArray(R"({"TrialBoundaries": [10, 80], "LeftFootEvents": 3})")
                                       << "LeftFootEvents is not a list";
    QTest::newRow("text in a pair") << QByteArray(R"({"TrialBoundaries": [10, 80], "LeftFootEvents": [[20, 30], ["a", 40]]})")
                                    << "LeftFootEvents entry 2 is not a [toe-off, heel-strike] pair";
    QTest::newRow("heel-strike before toe-off") << QByteArray(R"({"TrialBoundaries": [10, 80], "LeftFootEvents": [[50, 40]]})")
                                                << "LeftFootEvents entry 1";
    QTest::newRow("negative index") << QByteArray(R"({"TrialBoundaries": [-1, 80], "LeftFootEvents": []})")
                                    << "TrialBoundaries is not a pair";
    QTest::newRow("fractional index") << QByteArray(R"({"TrialBoundaries": [10, 80], "LeftFootEvents": [[20.5, 30]]})")
                                      << "LeftFootEvents entry 1";
    QTest::newRow("NaN as an index") << QByteArray(R"({"TrialBoundaries": [NaN, 80], "LeftFootEvents": []})")
                                     << "TrialBoundaries is not a pair";
}

void TestIpolGaitEvents::malformedSidecars()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, fragment);

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(writeFile(dir.filePath("9-9.json"), json));
    Recording recording = uniformRecording(100);
    std::vector<std::string> warnings;

    QVERIFY(!footpath::attachIpolGaitEvents(dir.filePath("9-9_lf.txt").toStdString(), recording, warnings));
    QCOMPARE(warnings.size(), std::size_t(1));
    QVERIFY2(QString::fromStdString(warnings.front()).contains(fragment), warnings.front().c_str());
    QVERIFY2(QString::fromStdString(warnings.front()).contains("gait events not attached"), warnings.front().c_str());
    QVERIFY(recording.reference.swings.empty() && recording.reference.notes.empty());
    QVERIFY(!recording.reference.hasTrialBoundaries);
}

QTEST_APPLESS_MAIN(TestIpolGaitEvents)

#include "tst_ipolgaitevents.moc"
