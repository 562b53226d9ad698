// Files too large to take: a 100 MB line is refused after reading 1 MiB of it, a 2 GB file before
// its samples are read, and a file that reaches the sample limit while being read stops there;
// each with a message naming the file, the line (or byte) and the bound. The files are generated
// while they are read, never stored, so the tests stay fast and the bytes a reader pulled show that
// it did not read on.
#include "io/Import.h"
#include "io/LineReader.h"
#include "io/SampleLimit.h"
#include "xbus/MtData2.h"
#include "xbus/XbusFrame.h"

#include <QtTest>

#include <algorithm>
#include <istream>
#include <sstream>
#include <streambuf>

using namespace footpath;

namespace {

const QByteArray kDelimitedHeader = "time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n";
const QByteArray kXsensHead = "// Update Rate: 100.0Hz\nPacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n";

/// A file that is never stored: `head`, then `pattern` over and over up to `size` bytes. It counts
/// the bytes the reader pulled.
class GeneratedFile : public std::streambuf {
public:
    GeneratedFile(QByteArray head, QByteArray pattern, std::size_t size)
        : head_(std::move(head)), pattern_(std::move(pattern)), size_(size), buffer_(64 * 1024)
    {
    }
    std::size_t bytesServed() const { return served_; }

protected:
    int_type underflow() override
    {
        if (end_ >= size_)
            return traits_type::eof();
        const std::size_t count = std::min(buffer_.size(), size_ - end_);
        for (std::size_t i = 0; i < count; ++i)
            buffer_[i] = byteAt(end_ + i);
        setg(buffer_.data(), buffer_.data(), buffer_.data() + count);
        end_ += count;
        served_ += count;
        return traits_type::to_int_type(buffer_[0]);
    }
    pos_type seekoff(off_type offset, std::ios_base::seekdir dir, std::ios_base::openmode mode) override
    {
        const auto here = static_cast<off_type>(end_) - (egptr() - gptr());
        const off_type base = dir == std::ios_base::beg ? 0 : dir == std::ios_base::cur ? here : off_type(size_);
        return seekpos(pos_type(base + offset), mode);
    }
    pos_type seekpos(pos_type position, std::ios_base::openmode) override
    {
        if (position < 0 || static_cast<std::size_t>(position) > size_)
            return pos_type(off_type(-1));
        end_ = static_cast<std::size_t>(position);
        setg(buffer_.data(), buffer_.data(), buffer_.data());
        return position;
    }

private:
    char byteAt(std::size_t offset) const
    {
        const auto headSize = static_cast<std::size_t>(head_.size());
        return offset < headSize ? head_[qsizetype(offset)]
                                 : pattern_[qsizetype((offset - headSize) % std::size_t(pattern_.size()))];
    }

    QByteArray head_;
    QByteArray pattern_;
    std::size_t size_;
    std::vector<char> buffer_;
    std::size_t end_ = 0;  ///< file offset just after the buffer's last byte
    std::size_t served_ = 0;
};

QByteArray mtbFrame(std::uint32_t k)
{
    MtData2Sample sample;
    sample.packetCounter = static_cast<std::uint16_t>(k % 65536u);
    sample.sampleTimeFine = k * 100u;
    sample.acceleration = Eigen::Vector3d(0.1, 0.2, 9.81);
    sample.rateOfTurn = Eigen::Vector3d(0.01, 0.02, 0.03);
    const std::vector<std::uint8_t> frame = encodeFrame({kXbusMasterBusId, XbusMid::MtData2, encodeMtData2(sample)});
    return QByteArray(reinterpret_cast<const char*>(frame.data()), qsizetype(frame.size()));
}

/// `count` samples of a file in the given format: everything the file holds, as stored bytes.
QByteArray smallFile(const QString& format, int count)
{
    QByteArray bytes = format == "delimited" ? kDelimitedHeader : format == "xsens-text" ? kXsensHead : QByteArray();
    for (int k = 0; k < count; ++k) {
        if (format == "delimited")
            bytes += QByteArray::number(k * 0.01, 'f', 2) + ",0.1,0.2,9.81,0.01,0.02,0.03\n";
        else if (format == "xsens-text")
            bytes += QByteArray::number(1000 + k) + '\t' + QByteArray::number(1000000 + k * 100)
                     + "\t0.1\t0.2\t9.81\t0.01\t0.02\t0.03\n";
        else
            bytes += mtbFrame(std::uint32_t(k));
    }
    return bytes;
}

ImportResult importGenerated(GeneratedFile& file, std::size_t size, const QString& name, const ImportOptions& options)
{
    std::istream in(&file);
    return importStream(in, size, name.toStdString(), options);
}

QString errorText(const ImportResult& result)
{
    return result.ok() ? QStringLiteral("(read without error)") : QString::fromStdString(result.error->text());
}

}  // namespace

class TestLargeFiles : public QObject {
    Q_OBJECT
private slots:
    void lineReader_splitsLinesAndTellsAnUnendedLastLine();
    void lineReader_takesALineOfExactlyTheBound();
    void lineReader_stopsAtTheBound();
    void oneLongLine_isRefusedAfterReadingTheBound_data();
    void oneLongLine_isRefusedAfterReadingTheBound();
    void twoGigabyteFile_isRefusedBeforeItsSamplesAreRead_data();
    void twoGigabyteFile_isRefusedBeforeItsSamplesAreRead();
    void sampleLimit_stopsReadingWhereItIsReached_data();
    void sampleLimit_stopsReadingWhereItIsReached();
    void defaultSampleLimit_namesThisComputersMemory();
};

void TestLargeFiles::lineReader_splitsLinesAndTellsAnUnendedLastLine()
{
    std::istringstream in("a\r\nb\n\nc");
    LineReader lines(in);
    std::string line;
    QVERIFY(lines.next(line));
    QCOMPARE(line, std::string("a"));
    QVERIFY(lines.terminated());
    QVERIFY(lines.next(line) && line == "b");
    QVERIFY(lines.next(line) && line.empty() && lines.terminated());
    QVERIFY(lines.next(line));
    QCOMPARE(line, std::string("c"));
    QVERIFY(!lines.terminated());
    QCOMPARE(lines.lineNumber(), std::size_t(4));
    QCOMPARE(lines.bytesRead(), std::size_t(7));
    QVERIFY(!lines.next(line));
    QVERIFY(!lines.overlong());
}

void TestLargeFiles::lineReader_takesALineOfExactlyTheBound()
{
    // Longer than the reader's 64 KiB buffer, so the line and its break arrive in separate reads.
    const std::size_t bound = 100000;
    std::istringstream in(std::string(bound, 'x') + "\ny");
    LineReader lines(in, bound);
    std::string line;
    QVERIFY(lines.next(line));
    QCOMPARE(line.size(), bound);
    QVERIFY(lines.terminated());
    QVERIFY(!lines.overlong());
    QVERIFY(lines.next(line) && line == "y");
}

void TestLargeFiles::lineReader_stopsAtTheBound()
{
    const std::size_t bound = 100000;
    std::istringstream in("first\n" + std::string(bound + 1, 'x') + "\nlast\n");
    LineReader lines(in, bound);
    std::string line;
    QVERIFY(lines.next(line) && line == "first");
    QVERIFY(lines.next(line));
    QVERIFY(lines.overlong());
    QCOMPARE(line.size(), bound);
    QCOMPARE(lines.lineNumber(), std::size_t(2));
    QVERIFY(!lines.next(line));  // reading stopped: "last" is never seen
    QCOMPARE(lines.overlongMessage(), std::string("the line is longer than 100000 bytes, the most a line of text may hold"));
}

void TestLargeFiles::oneLongLine_isRefusedAfterReadingTheBound_data()
{
    QTest::addColumn<QByteArray>("head");
    QTest::addColumn<QByteArray>("pattern");
    QTest::addColumn<QStringList>("columnMap");
    QTest::addColumn<QString>("expected");
    const QByteArray firstRow = "0,0.1,0.2,9.81,0.01,0.02,0.03\n";
    QTest::newRow("a 100 MB data row") << kDelimitedHeader + firstRow << QByteArray("0.25,") << QStringList()
                                       << "walk.csv:3: the line is longer than 1 MiB (1048576 bytes)";
    QTest::newRow("a 100 MB header") << QByteArray("time_s,") << QByteArray("acc_x,gyr_x,") << QStringList()
                                     << "walk.csv:1: the line is longer than 1 MiB";
    QTest::newRow("one 100 MB line, no header")
        << QByteArray() << QByteArray("0.5,")
        << QStringList{"time_s", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"}
        << "walk.csv:1: the line is longer than 1 MiB";
    QTest::newRow("an MT Manager export with a 100 MB row")
        << kXsensHead + "0\t0\t0.1\t0.2\t9.81\t0.01\t0.02\t0.03\n" << QByteArray("1\t") << QStringList()
        << "walk.csv:4: the line is longer than 1 MiB (1048576 bytes), the most a line of text may hold; expected "
           "one packet a line";
}

void TestLargeFiles::oneLongLine_isRefusedAfterReadingTheBound()
{
    QFETCH(QByteArray, head);
    QFETCH(QByteArray, pattern);
    QFETCH(QStringList, columnMap);
    QFETCH(QString, expected);
    const std::size_t size = std::size_t(head.size()) + 100 * 1000 * 1000;
    GeneratedFile file(head, pattern, size);
    ImportOptions options;
    for (const QString& role : columnMap)
        options.columnMap.push_back(role.toStdString());
    const ImportResult result = importGenerated(file, size, "walk.csv", options);
    QVERIFY2(errorText(result).startsWith(expected), qPrintable(errorText(result)));
    // Format detection reads the first 64 KiB, the reader the bound and a buffer beyond it.
    QVERIFY2(file.bytesServed() < kMaxTextLineLength_bytes + 256 * 1024, qPrintable(QString::number(file.bytesServed())));
}

void TestLargeFiles::twoGigabyteFile_isRefusedBeforeItsSamplesAreRead_data()
{
    QTest::addColumn<QByteArray>("head");
    QTest::addColumn<QByteArray>("pattern");
    QTest::addColumn<QString>("expected");
    const QByteArray row = "0.01,0.1,0.2,9.81,0.01,0.02,0.03\n";  // 33 bytes
    QTest::newRow("delimited") << kDelimitedHeader << row
                               << "walk.csv: the file holds about 65.1 million samples (2.1 GB at 33 bytes a row), more "
                                  "than the 5.0 million samples (14 hours at 100 Hz) a recording may hold; split the "
                                  "file into shorter recordings";
    QTest::newRow("MT Manager export") << kXsensHead << QByteArray("1\t100\t0.1\t0.2\t9.81\t0.01\t0.02\t0.03\n")
                                       << "walk.csv: the file holds about 63.2 million samples (2.1 GB at 34 bytes a row)";
    const QByteArray frame = mtbFrame(1);
    QTest::newRow(".mtb log") << QByteArray() << frame
                              << QStringLiteral("walk.csv: the file holds about %1 million samples (2.1 GB at %2 bytes "
                                                "a message), more than the 5.0 million samples")
                                     .arg(2147483648.0 / double(frame.size()) / 1e6, 0, 'f', 1)
                                     .arg(frame.size());
}

void TestLargeFiles::twoGigabyteFile_isRefusedBeforeItsSamplesAreRead()
{
    QFETCH(QByteArray, head);
    QFETCH(QByteArray, pattern);
    QFETCH(QString, expected);
    const std::size_t size = std::size_t(2) << 30;
    GeneratedFile file(head, pattern, size);
    ImportOptions options;
    options.maxSamples = 5000000;  // a computer whose memory holds 5 million samples
    QElapsedTimer clock;
    clock.start();
    const ImportResult result = importGenerated(file, size, "walk.csv", options);
    QVERIFY2(errorText(result).startsWith(expected), qPrintable(errorText(result)));
    QVERIFY2(file.bytesServed() <= 256 * 1024, qPrintable(QString::number(file.bytesServed())));
    QVERIFY2(clock.elapsed() < 1000, qPrintable(QString::number(clock.elapsed())));
}

void TestLargeFiles::sampleLimit_stopsReadingWhereItIsReached_data()
{
    QTest::addColumn<QString>("format");
    QTest::addColumn<QString>("expected");
    const QString limit = ": the file holds more than the 1000 samples (10 s at 100 Hz) a recording may hold; split the "
                          "file into shorter recordings";
    // The 1001st sample: after the header, or after the rate and column lines.
    QTest::newRow("delimited") << "delimited" << "walk:1002" + limit;
    QTest::newRow("MT Manager export") << "xsens-text" << "walk:1003" + limit;
    QTest::newRow(".mtb log") << "xsens-mtb" << "walk" + limit + " (stopped at byte offset ";
}

void TestLargeFiles::sampleLimit_stopsReadingWhereItIsReached()
{
    QFETCH(QString, format);
    QFETCH(QString, expected);
    // 1200 samples: the estimate from the first row is under twice the limit, so reading starts
    // and has to stop at the limit itself.
    const QByteArray bytes = smallFile(format, 1200);
    std::istringstream in(bytes.toStdString());
    ImportOptions options;
    options.maxSamples = 1000;
    const ImportResult result = importStream(in, std::size_t(bytes.size()), "walk", options);
    QVERIFY2(errorText(result).startsWith(expected), qPrintable(errorText(result)));

    options.maxSamples = 1200;
    std::istringstream again(bytes.toStdString());
    const ImportResult whole = importStream(again, std::size_t(bytes.size()), "walk", options);
    QVERIFY2(whole.ok(), qPrintable(errorText(whole)));
    QCOMPARE(whole.recording.samples.size(), std::size_t(1200));
}

void TestLargeFiles::defaultSampleLimit_namesThisComputersMemory()
{
    const std::size_t limit = defaultSampleLimit();
    // Any computer this runs on holds an hour at 100 Hz; none holds a billion samples' analysis.
    QVERIFY2(limit >= 360000 && limit < 1000000000, qPrintable(QString::number(limit)));
    const QString message = QString::fromStdString(tooManySamplesMessage(limit, {}, ImportOptions()));
    QVERIFY2(message.contains("analysing a sample takes about 1200 bytes of memory, and half of this computer's "),
             qPrintable(message));
    QVERIFY2(message.contains(" GB holds that many"), qPrintable(message));
}

QTEST_APPLESS_MAIN(TestLargeFiles)
#include "tst_largefiles.moc"
