#include "AnalysisSession.h"
#include "sim/WalkSimulator.h"

#include <QSignalSpy>
#include <QUndoStack>
#include <QtTest>

using namespace footpath;

namespace {

constexpr int kTimeout_ms = 20000;

/// A 15 m walk from a sensor with noise and a gyro bias, so ZARU and the detector thresholds
/// visibly change the estimate.
std::shared_ptr<const Recording> noisyWalk(double length_m = 15.0)
{
    WalkSimulatorConfig config;
    config.accNoiseStd_mps2 = 0.05;
    config.gyrNoiseStd_radps = 0.005;
    config.gyrBias_radps = Eigen::Vector3d(0.002, -0.003, 0.004);
    return std::make_shared<const Recording>(simulateWalk(straightLinePath(length_m), config).recording);
}

/// Waits until the session holds a finished result other than previous.
bool waitForNewResult(AnalysisSession& session, const std::shared_ptr<const Result>& previous)
{
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < kTimeout_ms) {
        if (session.result() && session.result() != previous && !session.isEstimating())
            return true;
        QTest::qWait(10);
    }
    return false;
}

/// The defaults with the 15-state filter, where ZARU has gyro bias states to correct.
Parameters withBiasStates()
{
    Parameters params;
    params.filter_states = static_cast<int>(FilterStates::Fifteen);
    return params;
}

double finalDistance(const std::shared_ptr<const Result>& a, const std::shared_ptr<const Result>& b)
{
    return (a->position_m.back() - b->position_m.back()).norm();
}

}  // namespace

class TestAnalysisSession : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { qRegisterMetaType<std::shared_ptr<const Result>>(); }

    void settingARecordingStartsAnEstimate()
    {
        AnalysisSession session;
        QSignalSpy resultChanged(&session, &AnalysisSession::resultChanged);
        QSignalSpy estimating(&session, &AnalysisSession::estimatingChanged);
        session.setRecording(noisyWalk(), RecordingInfo(), QStringLiteral("walk"));
        QVERIFY(session.isEstimating());
        QVERIFY(!session.result());  // the old result is gone at once
        QVERIFY(waitForNewResult(session, nullptr));
        QVERIFY(resultChanged.count() >= 2);  // cleared, then the estimate
        QCOMPARE(estimating.first().first().toBool(), true);
        QCOMPARE(estimating.last().first().toBool(), false);
        QVERIFY2(std::abs(session.result()->summary.pathLength_m - 15.0) < 1.0,
                 qPrintable(QString::number(session.result()->summary.pathLength_m)));
    }

    void changingAParameterReRunsTheEstimate_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("value");
        QTest::newRow("ZARU toggled") << "use_zaru" << (Parameters().use_zaru ? 0.0 : 1.0);
        QTest::newRow("detector chosen") << "detector" << static_cast<double>(DetectorKind::PaperC1C2C3);
        QTest::newRow("detector window") << "zv_window_s" << 0.1;
        QTest::newRow("filter size chosen") << "filter_states" << static_cast<double>(FilterStates::Nine);
    }

    void changingAParameterReRunsTheEstimate()
    {
        QFETCH(QString, name);
        QFETCH(double, value);
        AnalysisSession session;
        session.setParameters(withBiasStates(), QStringLiteral("15 states"));  // ZARU needs them
        session.setRecording(noisyWalk(), RecordingInfo(), QString());
        QVERIFY(waitForNewResult(session, nullptr));
        const auto before = session.result();
        QSignalSpy parametersChanged(&session, &AnalysisSession::parametersChanged);
        session.setParameter(name, value);
        QCOMPARE(parametersChanged.count(), 1);
        QCOMPARE(parameterValue(session.parameters(), *findParameterField(name.toStdString())), value);
        QVERIFY(waitForNewResult(session, before));
        QVERIFY2(finalDistance(before, session.result()) > 1e-4,
                 qPrintable(QString::number(finalDistance(before, session.result()))));
    }

    void undoRestoresTheParametersAndReRuns()
    {
        AnalysisSession session;
        session.setParameters(withBiasStates(), QStringLiteral("15 states"));
        session.setRecording(noisyWalk(), RecordingInfo(), QString());
        QVERIFY(waitForNewResult(session, nullptr));
        const auto original = session.result();
        const bool zaru = Parameters().use_zaru;
        session.setParameter(QStringLiteral("use_zaru"), zaru ? 0.0 : 1.0);
        QVERIFY(waitForNewResult(session, original));
        const auto toggled = session.result();

        session.undoStack()->undo();
        QCOMPARE(session.parameters().use_zaru, zaru);
        QVERIFY(waitForNewResult(session, toggled));
        QCOMPARE(finalDistance(session.result(), original), 0.0);  // the pipeline is deterministic

        const auto undone = session.result();
        session.undoStack()->redo();
        QCOMPARE(session.parameters().use_zaru, !zaru);
        QVERIFY(waitForNewResult(session, undone));
        QCOMPARE(finalDistance(session.result(), toggled), 0.0);
    }

    void aChoiceIsSetByItsIndexAndUndone()
    {
        AnalysisSession session;  // no recording: the parameters alone
        session.setParameter(QStringLiteral("detector"), static_cast<double>(DetectorKind::Mbgtd));
        QCOMPARE(session.parameters().detectorKind(), DetectorKind::Mbgtd);
        const FilterStates other =
            Parameters().filterStates() == FilterStates::Nine ? FilterStates::Fifteen : FilterStates::Nine;
        session.setParameter(QStringLiteral("filter_states"), static_cast<double>(other));
        QCOMPARE(session.parameters().filterStates(), other);
        QCOMPARE(session.undoStack()->count(), 2);
        session.undoStack()->undo();
        session.undoStack()->undo();
        QCOMPARE(session.parameters().detector, Parameters().detector);
        QCOMPARE(session.parameters().filter_states, Parameters().filter_states);
    }

    void rapidChangesOfOneFieldAreOneUndoStep()
    {
        AnalysisSession session;  // no recording: the parameters alone
        for (double value : {0.6, 0.7, 0.8, 0.9})
            session.setParameter(QStringLiteral("acc_std_max_mps2"), value);
        QCOMPARE(session.undoStack()->count(), 1);
        QCOMPARE(session.parameters().acc_std_max_mps2, 0.9);
        session.setParameter(QStringLiteral("gyr_max_radps"), 1.5);  // another field: a new step
        QCOMPARE(session.undoStack()->count(), 2);
        // Edit > Undo names the change as the panel does, by its label.
        QCOMPARE(session.undoStack()->undoText(),
                 QStringLiteral("Change ") + QString::fromUtf8(findParameterField("gyr_max_radps")->label));
        session.undoStack()->undo();
        session.undoStack()->undo();
        QCOMPARE(session.parameters().acc_std_max_mps2, Parameters().acc_std_max_mps2);
        QCOMPARE(session.parameters().gyr_max_radps, Parameters().gyr_max_radps);
    }

    void anUnchangedValueAddsNoStep()
    {
        AnalysisSession session;
        session.setParameter(QStringLiteral("acc_std_max_mps2"), Parameters().acc_std_max_mps2);
        session.setParameter(QStringLiteral("no_such_parameter"), 1.0);
        QCOMPARE(session.undoStack()->count(), 0);
    }

    void replacingTheSetIsOneStep()
    {
        AnalysisSession session;
        session.setParameter(QStringLiteral("acc_std_max_mps2"), 0.8);
        session.setParameter(QStringLiteral("use_zupt"), 0.0);
        const Parameters edited = session.parameters();
        const int before = session.undoStack()->count();
        session.setParameters(Parameters(), QStringLiteral("Reset to defaults"));
        QCOMPARE(session.undoStack()->count(), before + 1);
        QCOMPARE(session.undoStack()->undoText(), QStringLiteral("Reset to defaults"));
        QVERIFY(session.parameters().use_zupt);
        session.setParameters(Parameters(), QStringLiteral("Reset again"));  // nothing changes: no empty step
        QCOMPARE(session.undoStack()->count(), before + 1);
        session.undoStack()->undo();
        QCOMPARE(session.parameters().acc_std_max_mps2, edited.acc_std_max_mps2);
        QVERIFY(!session.parameters().use_zupt);
    }

    void anInvalidValueIsReportedInWords_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("value");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("C1 bounds crossed") << "acc_min_mps2" << 20.0 << "acc_max_mps2";
        QTest::newRow("out of range") << "q_att_rad" << 5.0 << "must be between";
    }

    void anInvalidValueIsReportedInWords()
    {
        QFETCH(QString, name);
        QFETCH(double, value);
        QFETCH(QString, mentions);
        AnalysisSession session;
        session.setRecording(noisyWalk(3.0), RecordingInfo(), QString());
        QVERIFY(waitForNewResult(session, nullptr));
        QSignalSpy failed(&session, &AnalysisSession::estimateFailed);
        session.setParameter(name, value);
        QVERIFY(failed.count() == 1 || failed.wait(kTimeout_ms));
        const QString message = failed.first().first().toString();
        QVERIFY2(message.contains(name) && message.contains(mentions), qPrintable(message));
        QVERIFY(!session.isEstimating());
    }

    void aClosedRecordingGetsNoResultOfTheOldOne()
    {
        AnalysisSession session;
        session.setRecording(noisyWalk(300.0), RecordingInfo(), QStringLiteral("long walk"));
        QVERIFY(session.isEstimating());
        session.setRecording(nullptr, RecordingInfo(), QString());  // closed while estimating
        QVERIFY(!session.result());
        QVERIFY(!session.isEstimating());
        QVERIFY(QTest::qWaitFor([&session] { return !session.isEstimating(); }, kTimeout_ms));
        QTest::qWait(100);
        QVERIFY(!session.result());
    }

    void aNewRecordingMovesTheTimeCursorAndSaysSo()
    {
        AnalysisSession session;
        session.setRecording(noisyWalk(3.0), RecordingInfo(), QString());
        session.setTimeCursor(4.0);
        QSignalSpy cursor(&session, &AnalysisSession::timeCursorChanged);
        Recording later = *noisyWalk(3.0);
        for (ImuSample& sample : later.samples)
            sample.time_s += 100.0;
        session.setRecording(std::make_shared<const Recording>(later), RecordingInfo(), QString());
        QCOMPARE(session.timeCursor(), 100.0);
        QCOMPARE(cursor.count(), 1);
    }
};

QTEST_MAIN(TestAnalysisSession)
#include "tst_analysissession.moc"
