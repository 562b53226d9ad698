// Both feet in the workspace: the left and the right file of an IPOL walk opened together in the
// real main window show both paths (2D and 3D, with their keys), the double support and the
// symmetry in the summary, and the report; one file afterwards is one foot again.
#include "AnalysisSession.h"
#include "AppSettings.h"
#include "MainWindow.h"
#include "OtherFootSession.h"
#include "RecordedInputPanel.h"
#include "SummaryPanel.h"
#include "TestData.h"
#include "TrajectoryView2D.h"
#include "TrajectoryView3D.h"

#include <QFileInfo>
#include <QGroupBox>
#include <QLabel>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTextBrowser>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>

using namespace footpath;

class TestBothFeet : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        qRegisterMetaType<std::shared_ptr<const Result>>();
    }

    void opensAPairAndShowsBothPathsAndTheDoubleSupport()
    {
        FOOTPATH_REQUIRE_DATASETS();
        const QString left = datasetPath(QStringLiteral("xsens-mtw-ipol/1-4_lf.txt"));
        const QString right = datasetPath(QStringLiteral("xsens-mtw-ipol/1-4_rf.txt"));
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_bothfeet"));
        MainWindow window(settings);
        // The right file first: the names, not the order, say which foot is which.
        QCOMPARE(window.openRecordings({right, left}), QString());
        QTRY_VERIFY_WITH_TIMEOUT(window.otherFoot()->bothFeet().has_value() && !window.session()->isEstimating(), 60000);
        QCOMPARE(window.session()->recordingPath(), left);
        QCOMPARE(window.otherFoot()->path(), right);
        QVERIFY(window.windowTitle().contains(QStringLiteral("1-4_lf.txt + 1-4_rf.txt")));

        // Both paths, in distinct colours, each with a key entry.
        const auto* view2D = window.findChild<TrajectoryView2D*>(QStringLiteral("trajectory2D"));
        QCOMPARE(view2D->pathLabel(), QStringLiteral("Left foot"));
        QCOMPARE(view2D->overlayCurves().size(), std::size_t(1));
        const QCPCurve* rightCurve = view2D->overlayCurves().front();
        QCOMPARE(rightCurve->name(), QStringLiteral("Right foot"));
        QCOMPARE(std::size_t(rightCurve->dataCount()), window.otherFoot()->result()->position_m.size());
        // The right foot is keyed below the plot beside the left (it had a box of its own over the
        // path while the left foot's entry was below).
        QVERIFY(view2D->findChild<QCustomPlot*>()->legend->hasItemWithPlottable(rightCurve));
        QVERIFY(!view2D->overlayLegend() || !view2D->overlayLegend()->visible());
        QVERIFY(rightCurve->pen().color() != view2D->pathColourAt(0));
        const auto* view3D = window.findChild<TrajectoryView3D*>(QStringLiteral("trajectory3D"));
        QCOMPARE(view3D->pathLabel(), QStringLiteral("Left foot"));
        QCOMPARE(view3D->overlays().size(), std::size_t(1));
        QCOMPARE(view3D->overlays().front().label, QStringLiteral("Right foot"));

        // Turned onto the left path, the right one walks beside it: at the same moment the feet
        // are at most a stride apart (1.5 m), not on another heading metres away.
        const Result& leftResult = *window.session()->result();
        const std::vector<Eigen::Vector3d>& aligned = window.otherFoot()->alignedPath();
        double largest = 0.0;
        for (std::size_t k = 0; k < std::min(aligned.size(), leftResult.position_m.size()); k += 10)
            largest = std::max(largest, (aligned[k] - leftResult.position_m[k]).head<2>().norm());
        QVERIFY2(largest < 1.5, qPrintable(QString::number(largest)));

        // The summary's "Both feet" figures are the computed ones.
        const BilateralGait& walk = *window.otherFoot()->bothFeet();
        QVERIFY2(walk.doubleSupport.meanPct > 15.0 && walk.doubleSupport.meanPct < 35.0,
                 qPrintable(QString::number(walk.doubleSupport.meanPct)));
        auto* summary = window.findChild<SummaryPanel*>();
        const auto* group = summary->findChild<QGroupBox*>(QStringLiteral("bothFeet"));
        QVERIFY(group && !group->isHidden());
        const QString doubleSupport = summary->findChild<QLabel*>(QStringLiteral("figure_doubleSupport"))->text();
        const QString expected = QLocale().toString(walk.doubleSupport.meanPct, 'f', 1);
        QVERIFY2(doubleSupport.startsWith(expected + QStringLiteral(" % of the gait cycle")), qPrintable(doubleSupport));
        const QString symmetry = summary->findChild<QLabel*>(QStringLiteral("figure_symmetryStrideTime"))->text();
        QVERIFY2(symmetry.contains(QRegularExpression(QStringLiteral("^-?\\d+[.,]\\d %$"))), qPrintable(symmetry));
        QVERIFY(!summary->findChild<QGroupBox*>(QStringLiteral("gaitFigures"))->isHidden());

        // The report carries both feet.
        QTemporaryDir dir;
        const QString pdf = dir.filePath(QStringLiteral("both.pdf"));
        QCOMPARE(window.writeReport(pdf), QString());
        QVERIFY(QFileInfo(pdf).size() > 10000);
        if (!QStandardPaths::findExecutable(QStringLiteral("pdftotext")).isEmpty()) {
            QProcess text;
            text.start(QStringLiteral("pdftotext"), {pdf, QStringLiteral("-")});
            QVERIFY(text.waitForFinished(60000));
            const QString report = QString::fromUtf8(text.readAllStandardOutput()).simplified();
            for (const QString& expectedText :
                 {QStringLiteral("1-4_lf.txt + 1-4_rf.txt"), QStringLiteral("Gait (heel strike to toe"),  // "off" is set with an ff ligature
                  QStringLiteral("Both feet"), QStringLiteral("Double support (both feet on the ground) ")
                                                   + QString::number(walk.doubleSupport.meanPct, 'f', 1)
                                                   + QStringLiteral(" % of the gait cycle"),
                  QStringLiteral("Symmetry index: stride length"), QStringLiteral("Figure 9. Gait stance")})
                QVERIFY2(report.contains(expectedText), qPrintable(expectedText));
        }

        // A parameter change re-estimates the right foot too.
        const std::shared_ptr<const Result> rightBefore = window.otherFoot()->result();
        window.session()->setParameter(QStringLiteral("gyr_max_radps"), 1.2);
        QTRY_VERIFY_WITH_TIMEOUT(window.otherFoot()->result() != rightBefore && !window.session()->isEstimating(), 60000);

        // One file again: one foot, one path, no "Both feet".
        window.openRecording(left);
        QVERIFY(!window.otherFoot()->isActive());
        QTRY_VERIFY_WITH_TIMEOUT(window.session()->result() && !window.session()->isEstimating(), 60000);
        QVERIFY(view2D->overlayCurves().empty());
        QCOMPARE(view2D->pathLabel(), QStringLiteral("Foot path"));
        QVERIFY(group->isHidden());
    }

    void theRightFootsFileAndFilesAreThereToo()
    {
        // The input panel showed only the left file (none of the right file's gaps), and CSV
        // export wrote only the left foot.
        FOOTPATH_REQUIRE_DATASETS();
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_bothfeet"));
        MainWindow window(settings);
        const QString right = datasetPath(QStringLiteral("xsens-mtw-ipol/1-1_rf.txt"));
        QCOMPARE(window.openRecordings({datasetPath(QStringLiteral("xsens-mtw-ipol/1-1_lf.txt")), right}), QString());
        QTRY_VERIFY_WITH_TIMEOUT(window.otherFoot()->bothFeet().has_value() && !window.session()->isEstimating(), 60000);
        auto* panel = window.findChild<RecordedInputPanel*>();
        QVERIFY(panel);
        const QString shown = panel->findChild<QTextBrowser*>()->toPlainText();
        QVERIFY2(shown.contains(QStringLiteral("Right foot")) && shown.contains(QStringLiteral("1-1_rf.txt")), qPrintable(shown));
        const ImportResult rightRead = importRecording(right.toStdString());
        QVERIFY(rightRead.info.gaps.count > 0);
        QVERIFY2(shown.contains(QStringLiteral("%1 (about %2 samples lost)").arg(rightRead.info.gaps.count).arg(rightRead.info.gaps.missingSamples)),
                 qPrintable(shown));

        QTemporaryDir dir;
        QCOMPARE(window.exportCsvInto(dir.path()), QString());
        for (const char* name : {"1-1_lf-trajectory.csv", "1-1_lf-steps.csv", "1-1_lf-summary.csv", "1-1_rf-trajectory.csv",
                                 "1-1_rf-steps.csv", "1-1_rf-summary.csv", "1-1_lf-parameters.csv"})
            QVERIFY2(QFileInfo(dir.filePath(QString::fromLatin1(name))).size() > 100, name);
        QFile steps(dir.filePath(QStringLiteral("1-1_rf-steps.csv")));
        QVERIFY(steps.open(QIODevice::ReadOnly));
        QCOMPARE(steps.readAll().count('\n'), qsizetype(window.otherFoot()->result()->steps.size() + 1));
    }

    void combinesBothFeetOncePerParameterChange()
    {
        // Each foot is estimated again after a change and each result used to combine the pair:
        // the first time with the other foot's estimate for the old parameters.
        FOOTPATH_REQUIRE_DATASETS();
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_bothfeet"));
        MainWindow window(settings);
        QCOMPARE(window.openRecordings({datasetPath(QStringLiteral("xsens-mtw-ipol/1-4_lf.txt")),
                                        datasetPath(QStringLiteral("xsens-mtw-ipol/1-4_rf.txt"))}),
                 QString());
        AnalysisSession& session = *window.session();
        OtherFootSession& rightFoot = *window.otherFoot();
        QTRY_VERIFY_WITH_TIMEOUT(rightFoot.bothFeet().has_value() && !session.isEstimating(), 60000);

        struct Combined {
            std::shared_ptr<const Result> left, right;
        };
        std::vector<Combined> combinations;
        connect(&rightFoot, &OtherFootSession::changed, this,
                [&] { combinations.push_back({session.result(), rightFoot.result()}); });
        const auto changeAndWait = [&](const std::vector<double>& values) {
            const std::shared_ptr<const Result> leftBefore = session.result(), rightBefore = rightFoot.result();
            for (double value : values)  // in a row, as a dragged slider sends them
                session.setParameter(QStringLiteral("gyr_max_radps"), value);
            QTRY_VERIFY_WITH_TIMEOUT(session.result() != leftBefore && rightFoot.result() != rightBefore
                                         && !session.isEstimating(),
                                     60000);
            QTest::qWait(100);  // a late second combination would come now
        };

        changeAndWait({1.2});
        QCOMPARE(combinations.size(), std::size_t(1));
        // Of the two new estimates, and the figures shown are theirs.
        QCOMPARE(combinations.front().left, session.result());
        QCOMPARE(combinations.front().right, rightFoot.result());
        const BilateralGait expected = analyseBilateralGait(*session.result(), *rightFoot.result());
        QVERIFY(rightFoot.bothFeet().has_value());
        QCOMPARE(rightFoot.bothFeet()->doubleSupport.meanPct, expected.doubleSupport.meanPct);

        combinations.clear();
        changeAndWait({1.3, 1.4, 1.5});
        QCOMPARE(combinations.size(), std::size_t(1));
        QCOMPARE(combinations.front().left, session.result());
        QCOMPARE(combinations.front().right, rightFoot.result());
    }

    void refusesTwoFilesOfOneFoot()
    {
        FOOTPATH_REQUIRE_DATASETS();
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_bothfeet"));
        MainWindow window(settings);
        const QString problem = window.openRecordings({datasetPath(QStringLiteral("xsens-mtw-ipol/1-4_lf.txt")),
                                                       datasetPath(QStringLiteral("xsens-mtw-ipol/10-1_lf.txt"))});
        QVERIFY2(problem.contains(QStringLiteral("both named as the left foot")), qPrintable(problem));
        QVERIFY(!window.otherFoot()->isActive());
        QVERIFY(!window.session()->recording());
        // A folder of many walks: which pair is meant is not for Footpath to guess.
        const QString folder = window.openRecordings({datasetPath(QStringLiteral("xsens-mtw-ipol"))});
        QVERIFY2(folder.contains(QStringLiteral("6 left/right pairs")), qPrintable(folder));
        QVERIFY(!window.session()->recording());
    }

    void opensTheOnePairOfAFolder()
    {
        FOOTPATH_REQUIRE_DATASETS();
        QTemporaryDir dir;
        for (const char* name : {"10-1_lf.txt", "10-1_rf.txt", "10-1.json"})
            QVERIFY(QFile::copy(datasetPath(QStringLiteral("xsens-mtw-ipol/") + QLatin1String(name)), dir.filePath(QLatin1String(name))));
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_bothfeet"));
        MainWindow window(settings);
        QCOMPARE(window.openRecordings({dir.path()}), QString());
        QTRY_VERIFY_WITH_TIMEOUT(window.otherFoot()->bothFeet().has_value() && !window.session()->isEstimating(), 60000);
        QCOMPARE(QFileInfo(window.session()->recordingPath()).fileName(), QStringLiteral("10-1_lf.txt"));
        QCOMPARE(QFileInfo(window.otherFoot()->path()).fileName(), QStringLiteral("10-1_rf.txt"));
    }
};

QTEST_MAIN(TestBothFeet)
#include "tst_bothfeet.moc"
