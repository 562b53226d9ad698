// The import dialog: the column map it proposes from the header and the values, the header shown
// as the header, the file's own line numbers, and the check that refuses a reading that cannot be
// right before Open.
#include "ImportDialog.h"
#include "TestData.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace footpath;

namespace {

QStringList roles(const ImportDialog& dialog)
{
    QStringList out;
    for (const std::string& role : dialog.options().columnMap)
        out << QString::fromStdString(role);
    return out;
}

QComboBox* roleBox(ImportDialog& dialog, int column)
{
    return qobject_cast<QComboBox*>(dialog.findChild<QTableWidget*>()->cellWidget(0, column));
}

QPushButton* openButton(ImportDialog& dialog)
{
    return dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
}

QString checkText(ImportDialog& dialog)
{
    return dialog.findChild<QLabel*>(QStringLiteral("importCheck"))->text();
}

}  // namespace

class TestImportDialog : public QObject {
    Q_OBJECT
private slots:
    void headerTitlesTheColumnsAndRolesComeFromItsNames()
    {
        // A logger's export with gyroscope names the reader does not know. The dialog proposed
        // time_ms (a 200 kHz rate for a seconds column) and the magnetometer's x as a pressure,
        // and showed the header as the first data row.
        QByteArray text = "Time,AX,AY,AZ,Roll rate,Pitch rate,Yaw rate,MX,MY,MZ\n";
        for (int k = 0; k < 400; ++k)
            text += QByteArray::number(0.005 * k, 'f', 3) + ",0.01,0.02,-1.0,0.01,0.0,0.02,0.21,0.05,-0.43\n";
        QTemporaryDir dir;
        ImportDialog dialog(writeFileIn(dir, "export.csv", text), QStringLiteral("missing columns"), ImportOptions());
        auto* table = dialog.findChild<QTableWidget*>();
        QCOMPARE(table->horizontalHeaderItem(0)->text(), QStringLiteral("1: Time"));
        QCOMPARE(table->horizontalHeaderItem(4)->text(), QStringLiteral("5: Roll rate"));
        QCOMPARE(table->verticalHeaderItem(0)->text(), QStringLiteral("role"));
        QCOMPARE(table->verticalHeaderItem(1)->text(), QStringLiteral("line 2"));  // the first data line
        QCOMPARE(table->item(1, 0)->text(), QStringLiteral("0.000"));
        QVERIFY(dialog.findChild<QLabel*>(QStringLiteral("importHeaderNote"))->text().contains(QStringLiteral("Line 1")));
        QCOMPARE(roles(dialog), (QStringList{"time_s", "acc_x", "acc_y", "acc_z", "skip", "skip", "skip", "mag_x",
                                             "mag_y", "mag_z"}));
        // No gyroscope yet: Open waits, and the dialog says why.
        QVERIFY(!openButton(dialog)->isEnabled());
        QVERIFY2(checkText(dialog).contains(QStringLiteral("gyr_x")), qPrintable(checkText(dialog)));
        for (int c = 4; c < 7; ++c)
            roleBox(dialog, c)->setCurrentText(QStringLiteral("gyr_") + QChar('x' + (c - 4)));
        QTRY_VERIFY(openButton(dialog)->isEnabled());
        QVERIFY2(checkText(dialog).contains(QStringLiteral("200 Hz")), qPrintable(checkText(dialog)));
        // The old proposals are refused before Open, each with its reason.
        roleBox(dialog, 0)->setCurrentText(QStringLiteral("time_ms"));
        QTRY_VERIFY2(checkText(dialog).contains(QStringLiteral("rate is 2e+05 Hz")), qPrintable(checkText(dialog)));
        QVERIFY(!openButton(dialog)->isEnabled());
        roleBox(dialog, 0)->setCurrentText(QStringLiteral("time_s"));
        roleBox(dialog, 7)->setCurrentText(QStringLiteral("pressure_pa"));
        QTRY_VERIFY2(checkText(dialog).contains(QStringLiteral("no barometer")), qPrintable(checkText(dialog)));
        QVERIFY(!checkText(dialog).contains(QStringLiteral("rate is")));
        QVERIFY(!openButton(dialog)->isEnabled());
    }

    void headerlessFileKeepsItsLineNumbersAndNoFalsePressure()
    {
        // Unit-norm floats in column 8 were proposed as a pressure (barometric height +-3000 m).
        // The file starts with an empty line, as some ecg-xmu files do: the preview counts it, as
        // the reader's messages do.
        QByteArray text = "\n";
        for (int k = 0; k < 300; ++k)
            text += QByteArray::number(1000 + 10 * k) + ",0.3,-0.2,9.79,0.01,-0.02,0.005,0.5512,0.1021,-0.8277\n";
        QTemporaryDir dir;
        ImportDialog dialog(writeFileIn(dir, "log.txt", text), QStringLiteral("no header row"), ImportOptions());
        auto* table = dialog.findChild<QTableWidget*>();
        QCOMPARE(table->verticalHeaderItem(1)->text(), QStringLiteral("line 2"));
        QCOMPARE(table->horizontalHeaderItem(0)->text(), QStringLiteral("column 1"));
        QCOMPARE(roles(dialog).mid(0, 8), (QStringList{"time_ms", "acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z", "skip"}));
        QVERIFY(openButton(dialog)->isEnabled());
        QVERIFY2(checkText(dialog).contains(QStringLiteral("no air pressure")), qPrintable(checkText(dialog)));
        QVERIFY2(checkText(dialog).contains(QStringLiteral("100 Hz")), qPrintable(checkText(dialog)));
    }
};

QTEST_MAIN(TestImportDialog)
#include "tst_importdialog.moc"
