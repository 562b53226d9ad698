// Placeholder while the test is being written (replaced in this change).
#include <QtTest>

class TestSourcesVertical : public QObject {
    Q_OBJECT
private slots:
    void pending() { QSKIP("being written"); }
};

QTEST_GUILESS_MAIN(TestSourcesVertical)
#include "tst_sources_vertical.moc"
