// Placeholder while the test is being written (replaced in this change).
#include <QtTest>

class TestCliCompare : public QObject {
    Q_OBJECT
private slots:
    void pending() { QSKIP("being written"); }
};

QTEST_GUILESS_MAIN(TestCliCompare)
#include "tst_cli_compare.moc"
