// The list of column names a reader puts in a message: all of them while it is short, cut at 300
// characters with " ..." (and, if asked, the number of names) when a header of thousands of names
// or a binary file's "header line" would flood the message.
#include "io/ColumnNames.h"

#include <QtTest>

#include <string>
#include <vector>

using namespace footpath;

namespace {

/// `count` names of four characters ("n000", "n001", ...): joined, each takes six with ", ".
std::vector<std::string> numberedNames(int count)
{
    std::vector<std::string> names;
    for (int k = 0; k < count; ++k)
        names.push_back(QStringLiteral("n%1").arg(k, 3, 10, QLatin1Char('0')).toStdString());
    return names;
}

}  // namespace

class TestColumnNames : public QObject {
    Q_OBJECT
private slots:
    void aShortListIsListedWhole()
    {
        const std::vector<std::string> names{"time_s", "acc_x", "temperature"};
        QCOMPARE(listedColumnNames(names, ColumnCount::Stated), std::string("time_s, acc_x, temperature"));
        QCOMPARE(listedColumnNames(names, ColumnCount::Omitted), std::string("time_s, acc_x, temperature"));
        QCOMPARE(listedColumnNames({}, ColumnCount::Stated), std::string());
        QCOMPARE(listedColumnNames({"only"}, ColumnCount::Stated), std::string("only"));
    }

    void threeHundredCharactersAreNotCut()
    {
        // 50 names of 4 characters and 49 separators: 298 characters; one more name of 0 adds 2.
        std::vector<std::string> names = numberedNames(50);
        names.push_back("");
        const std::string listed = listedColumnNames(names, ColumnCount::Stated);
        QCOMPARE(listed.size(), std::size_t(300));
        QVERIFY(listed.find("...") == std::string::npos);
    }

    void aLongListIsCutAtThreeHundredCharacters()
    {
        // 100 names take 598 characters; the first 300 are the first 50 names, each with ", ".
        const std::vector<std::string> names = numberedNames(100);
        std::string first50;
        for (int k = 0; k < 50; ++k)
            first50 += names[std::size_t(k)] + ", ";
        QCOMPARE(first50.size(), std::size_t(300));
        QCOMPARE(listedColumnNames(names, ColumnCount::Omitted), first50 + " ...");
        QCOMPARE(listedColumnNames(names, ColumnCount::Stated), first50 + " ... (100 columns)");

        // One cell over the limit is cut too: a binary file read as a header line.
        const std::string binary(100000, 'x');
        QCOMPARE(listedColumnNames({binary}, ColumnCount::Omitted), std::string(300, 'x') + " ...");
        QCOMPARE(listedColumnNames({binary}, ColumnCount::Stated), std::string(300, 'x') + " ... (1 column)");
    }

    void aCutNeverSplitsACharacter()
    {
        // 299 ASCII characters, then two-byte characters (ü is 0xC3 0xBC): byte 300 is the second
        // byte of one, so the cut moves back to the character's start.
        const std::string name = std::string(299, 'x') + "\xC3\xBC\xC3\xBC\xC3\xBC";
        const std::string listed = listedColumnNames({name}, ColumnCount::Omitted);
        QCOMPARE(listed, std::string(299, 'x') + " ...");
        QVERIFY(QString::fromStdString(listed).toStdString() == listed);  // valid UTF-8 round-trips
        // A three-byte character (€, 0xE2 0x82 0xAC) over the limit is kept whole or dropped whole.
        for (std::size_t lead = 297; lead <= 300; ++lead) {
            const std::string euro = std::string(lead, 'x') + "\xE2\x82\xAC\xE2\x82\xAC";
            const std::string cut = listedColumnNames({euro}, ColumnCount::Omitted);
            QVERIFY2(QString::fromStdString(cut).toStdString() == cut, qPrintable(QString::number(lead)));
        }
    }
};

QTEST_APPLESS_MAIN(TestColumnNames)
#include "tst_columnnames.moc"
