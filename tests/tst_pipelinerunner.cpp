#include "PipelineRunner.h"
#include "sim/WalkSimulator.h"

#include <QSignalSpy>
#include <QtTest>

using namespace footpath;

namespace {

std::shared_ptr<const Recording> simulatedRecording(double length_m)
{
    return std::make_shared<const Recording>(simulateWalk(straightLinePath(length_m), WalkSimulatorConfig()).recording);
}

}  // namespace

class TestPipelineRunner : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { qRegisterMetaType<std::shared_ptr<const Result>>(); }

    void reportsTheResultOffTheGuiThread()
    {
        PipelineRunner runner;
        QSignalSpy finished(&runner, &PipelineRunner::finished);
        runner.run(simulatedRecording(10.0), Parameters());
        QVERIFY(finished.wait(10000));
        const auto result = finished.first().first().value<std::shared_ptr<const Result>>();
        QVERIFY(result);
        QVERIFY(std::abs(result->summary.pathLength_m - 10.0) < 0.5);
    }

    void aNewerRunReplacesTheOlderOne()
    {
        PipelineRunner runner;
        QSignalSpy finished(&runner, &PipelineRunner::finished);
        runner.run(simulatedRecording(300.0), Parameters());
        runner.run(simulatedRecording(40.0), Parameters());
        runner.run(simulatedRecording(5.0), Parameters());
        QVERIFY(finished.wait(20000));
        QTest::qWait(200);  // nothing else may arrive
        QCOMPARE(finished.count(), 1);
        const auto result = finished.first().first().value<std::shared_ptr<const Result>>();
        QVERIFY(std::abs(result->summary.pathLength_m - 5.0) < 0.5);
    }

    void theNextRunFillsTheMemoryOfAResultNobodyHolds()
    {
        PipelineRunner runner;
        QSignalSpy finished(&runner, &PipelineRunner::finished);
        const auto recording = simulatedRecording(10.0);
        runner.run(recording, Parameters());
        QVERIFY(finished.wait(10000));
        auto first = finished.takeFirst().first().value<std::shared_ptr<const Result>>();
        const Result copy = *first;
        const double* const firstTimes = first->time_s.data();

        // While it is held, the next run fills memory of its own.
        runner.run(recording, Parameters());
        QVERIFY(finished.wait(10000));
        auto second = finished.takeFirst().first().value<std::shared_ptr<const Result>>();
        QVERIFY(second->time_s.data() != firstTimes);

        // Dropped, its memory goes to the next run, and the result held meanwhile is untouched.
        first.reset();
        runner.run(recording, Parameters());
        QVERIFY(finished.wait(10000));
        const auto third = finished.takeFirst().first().value<std::shared_ptr<const Result>>();
        QCOMPARE(third->time_s.data(), firstTimes);
        QVERIFY(third->position_m == copy.position_m && second->position_m == copy.position_m);
        QVERIFY(third->errorStd == copy.errorStd && third->flags.stance == copy.flags.stance);
    }

    void aResultMayOutliveItsRunner()
    {
        std::shared_ptr<const Result> kept;
        {
            PipelineRunner runner;
            QSignalSpy finished(&runner, &PipelineRunner::finished);
            runner.run(simulatedRecording(5.0), Parameters());
            QVERIFY(finished.wait(10000));
            kept = finished.first().first().value<std::shared_ptr<const Result>>();
        }
        QVERIFY(std::abs(kept->summary.pathLength_m - 5.0) < 0.5);
        kept.reset();  // freed: there is no runner to take it (AddressSanitizer checks the rest)
    }

    void invalidParametersAreReportedInWords()
    {
        PipelineRunner runner;
        QSignalSpy failed(&runner, &PipelineRunner::failed);
        Parameters bad;
        bad.acc_min_mps2 = 20.0;
        runner.run(simulatedRecording(2.0), bad);
        QVERIFY(failed.wait(10000));
        QVERIFY(failed.first().first().toString().contains("acc_min_mps2"));
    }
};

QTEST_MAIN(TestPipelineRunner)
#include "tst_pipelinerunner.moc"
