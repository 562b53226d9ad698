// Placeholder while the test is being written (replaced in this change).
#include <QtTest>

class TestMotionview : public QObject {
    Q_OBJECT
private slots:
    void pending() { QSKIP("being written"); }
};

QTEST_GUILESS_MAIN(TestMotionview)
#include "tst_motionview.moc"
