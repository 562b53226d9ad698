// The structured filter and smoother (ErrorStateEkf, RtsSmoother: block products, the
// Bryson-Frazier backward pass) against the textbook dense implementation of the same estimator
// (DenseReferenceFilter): the speed must not change a result.
#include "DenseReferenceFilter.h"
#include "TestData.h"
#include "io/Import.h"
#include "nav/Pipeline.h"
#include "sim/WalkSimulator.h"

#include <QtTest>

using namespace footpath;

namespace {

struct Disagreement {
    double position_m = 0.0;
    double velocity_mps = 0.0;
    double pathLength_m = 0.0;  ///< of the reference path, for scale
};

Disagreement compare(const Recording& recording, const Parameters& params)
{
    const PipelineOutput structured = runPipeline(recording, params);
    const DenseReferenceOutput dense = runDenseReference(recording, params);
    if (!structured.error.empty() || !dense.error.empty())
        qFatal("%s%s", structured.error.c_str(), dense.error.c_str());
    if (structured.result.position_m.size() != dense.position_m.size())
        qFatal("%zu structured samples, %zu dense ones", structured.result.position_m.size(), dense.position_m.size());
    Disagreement worst;
    for (std::size_t k = 0; k < dense.position_m.size(); ++k) {
        worst.position_m = std::max(worst.position_m, (structured.result.position_m[k] - dense.position_m[k]).norm());
        worst.velocity_mps = std::max(worst.velocity_mps, (structured.result.velocity_mps[k] - dense.velocity_mps[k]).norm());
        if (k > 0)
            worst.pathLength_m += (dense.position_m[k] - dense.position_m[k - 1]).norm();
    }
    return worst;
}

Parameters configuration(const QString& name)
{
    if (name == "paper")
        return guo2015Parameters();  // C1/C2/C3, 15 states, ZUPT+ZARU, filter only
    Parameters params;  // the defaults: 9 states, ZUPT, smoother
    if (name == "15 states, smoother") {
        params.filter_states = static_cast<int>(FilterStates::Fifteen);
        params.use_zaru = true;
    } else if (name == "9 states, filter") {
        params.estimator = static_cast<int>(EstimatorKind::Ekf);
    }
    return params;
}

void addConfigurations()
{
    QTest::addColumn<QString>("name");
    for (const char* name : {"defaults", "9 states, filter", "15 states, smoother", "paper"})
        QTest::newRow(name) << QString(name);
}

void verifyAgreement(const Disagreement& worst)
{
    qInfo("largest difference %.3g m, %.3g m/s over a %.1f m path", worst.position_m, worst.velocity_mps,
          worst.pathLength_m);
    QVERIFY(worst.pathLength_m > 20.0);  // a walk, not a standstill that agrees trivially
    QVERIFY2(worst.position_m < 1e-9, qPrintable(QString::number(worst.position_m)));
    QVERIFY2(worst.velocity_mps < 1e-9, qPrintable(QString::number(worst.velocity_mps)));
}

}  // namespace

class TestDenseReference : public QObject {
    Q_OBJECT
private slots:
    void simulatedWalkAgrees_data() { addConfigurations(); }
    void simulatedWalkAgrees()
    {
        QFETCH(QString, name);
        // Two laps of a 20 x 10 m rectangle with MTi-class noise and biases (about a minute).
        std::vector<Eigen::Vector3d> path = closedRectanglePath(20.0, 10.0);
        const std::vector<Eigen::Vector3d> lap = path;
        path.insert(path.end(), lap.begin() + 1, lap.end());
        const SimulatedWalk walk = simulateWalk(path, mtiClassSensor(100.0, 7));
        verifyAgreement(compare(walk.recording, configuration(name)));
    }

    void realWalkAgrees_data() { addConfigurations(); }
    void realWalkAgrees()
    {
        QFETCH(QString, name);
        const QString file = datasetPath("pyshoe-vicon/2017-11-22-11-22-03.csv");
        if (!QFile::exists(file))
            QSKIP(qPrintable(file + " not found (set FOOTPATH_DATASETS)"));
        const ImportResult read = importRecording(file.toStdString());
        QVERIFY(read.ok());
        verifyAgreement(compare(read.recording, configuration(name)));
    }

    void otherSourcesAreRefused()
    {
        Parameters params;
        params.use_hdr = true;
        const SimulatedWalk walk = simulateWalk(straightLinePath(5.0), mtiClassSensor(100.0, 1));
        QVERIFY(!runDenseReference(walk.recording, params).error.empty());
    }
};

QTEST_GUILESS_MAIN(TestDenseReference)
#include "tst_densereference.moc"
