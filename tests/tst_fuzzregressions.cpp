// Inputs that broke a reader (found by the libFuzzer targets in tests/fuzz or by the robustness
// review), kept under tests/fuzz/regressions/ and fed to the reader as a user would: each must end
// in a clear message or a usable recording with a warning, never a crash or samples with NaN.
#include "io/Import.h"
#include "nav/InputCheck.h"

#include <QtTest>

using namespace footpath;

namespace {

QString regressionFile(const QString& name)
{
    return QStringLiteral(FOOTPATH_SOURCE_DIR "/tests/fuzz/regressions/") + name;
}

}  // namespace

class TestFuzzRegressions : public QObject {
    Q_OBJECT

private slots:
    void input_givesAClearOutcome_data();
    void input_givesAClearOutcome();
};

void TestFuzzRegressions::input_givesAClearOutcome_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("format");
    QTest::addColumn<int>("expectedSamples");  // -1: the import must fail
    QTest::addColumn<QString>("expectedText");  // in the error, or in one of the warnings

    // A checksum-valid MTData2 message can carry NaN or Inf floats; before, they went into the
    // recording and every estimated state after them was NaN.
    QTest::newRow("mtb: NaN acceleration, Inf rate of turn")
        << "mtb-nan-acceleration.mtb" << "xsens-mtb" << 3
        << "skipped 2 data message(s) whose acceleration or rate of turn is not a finite number";
    QTest::newRow("mtb: nothing but non-finite samples")
        << "mtb-only-nan.mtb" << "xsens-mtb" << -1
        << "2 data message(s) hold an acceleration or rate of turn that is not a finite number";
}

void TestFuzzRegressions::input_givesAClearOutcome()
{
    QFETCH(QString, file);
    QFETCH(QString, format);
    QFETCH(int, expectedSamples);
    QFETCH(QString, expectedText);

    ImportOptions options;
    options.format = format.toStdString();
    const ImportResult result = importRecording(regressionFile(file).toStdString(), options);
    if (expectedSamples < 0) {
        QVERIFY2(!result.ok(), "the damaged file was accepted");
        QVERIFY2(QString::fromStdString(result.error->message).contains(expectedText), result.error->message.c_str());
        return;
    }
    QVERIFY2(result.ok(), result.ok() ? "" : result.error->text().c_str());
    QCOMPARE(result.recording.samples.size(), std::size_t(expectedSamples));
    QVERIFY(describeUnusableSamples(result.recording.samples).empty());
    QStringList warnings;
    for (const std::string& warning : result.recording.warnings)
        warnings << QString::fromStdString(warning);
    QVERIFY2(!warnings.filter(expectedText).isEmpty(), qPrintable("warnings: " + warnings.join(" | ")));
}

QTEST_APPLESS_MAIN(TestFuzzRegressions)
#include "tst_fuzzregressions.moc"
