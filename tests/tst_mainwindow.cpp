// The workspace as a user drives it: open a file, tune a slider, toggle ZARU, undo, switch language.
#include "AnalysisSession.h"
#include "AppSettings.h"
#include "LivePanel.h"
#include "LiveViews.h"
#include "MainWindow.h"
#include "ParameterPanel.h"
#include "SignalPlots.h"
#include "StanceFlagsPlot.h"
#include "TrajectoryView2D.h"
#include "TrajectoryView3D.h"
#include "sim/WalkSimulator.h"

#include <QCheckBox>
#include <QMenuBar>
#include <QSignalSpy>
#include <QSlider>
#include <QTabWidget>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTranslator>
#include <QUndoStack>
#include <QtTest>
#include <qcustomplot.h>

using namespace footpath;

namespace {

QString writeSimulatedWalk(const QTemporaryDir& dir, std::size_t& samples)
{
    const SimulatedWalk walk = simulateWalk(closedRectanglePath(10.0, 5.0), WalkSimulatorConfig());
    const QString path = dir.filePath("walk.csv");
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write("time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n");
    for (const ImuSample& s : walk.recording.samples)
        file.write(QString::asprintf("%.4f,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", s.time_s, s.acc_mps2.x(), s.acc_mps2.y(),
                                     s.acc_mps2.z(), s.gyr_radps.x(), s.gyr_radps.y(), s.gyr_radps.z())
                       .toUtf8());
    samples = walk.recording.samples.size();
    return path;
}

}  // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        qRegisterMetaType<std::shared_ptr<const Result>>();
        QVERIFY(dir_.isValid());
        path_ = writeSimulatedWalk(dir_, samples_);
        QVERIFY(!path_.isEmpty());
    }

    void opensAFileAndThePlotsHoldItsSamples()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        QSignalSpy shown(&window, &MainWindow::resultShown);
        window.openRecording(path_);
        QVERIFY(shown.wait(30000));
        QCOMPARE(window.session()->recording()->samples.size(), samples_);
        const auto* plots = window.findChild<SignalPlots*>(QStringLiteral("signalPlots"));
        QVERIFY(plots);
        QCOMPARE(std::size_t(plots->graph(SignalPlots::Channel::AccX)->dataCount()), samples_);
        QVERIFY(window.session()->result()->summary.steps > 10);
        QVERIFY(settings.recentFiles().contains(path_));
    }

    void movingASliderReRunsAndUndoRestores()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        QSignalSpy shown(&window, &MainWindow::resultShown);
        window.openRecording(path_);
        QVERIFY(shown.wait(30000));
        const std::shared_ptr<const Result> before = window.session()->result();

        auto* slider = window.findChild<QSlider*>(QStringLiteral("slider_acc_std_max_mps2"));
        QVERIFY(slider);
        slider->setValue(slider->minimum() + (slider->maximum() - slider->minimum()) / 100);  // 0.2 m/s²: a strict C2
        QTRY_VERIFY_WITH_TIMEOUT(window.session()->result() != before && window.session()->result(), 30000);
        QVERIFY(window.session()->parameters().acc_std_max_mps2 < Parameters().acc_std_max_mps2);
        QVERIFY(window.session()->result()->flags.c2 != before->flags.c2);

        window.session()->undoStack()->undo();
        QCOMPARE(window.session()->parameters().acc_std_max_mps2, Parameters().acc_std_max_mps2);
        QTRY_VERIFY_WITH_TIMEOUT(window.session()->result() && window.session()->result()->flags.c2 == before->flags.c2,
                                 30000);
    }

    void liveViewsSitBesideTheRecordedOnesAndFollowTheParameters()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        auto* live = window.findChild<LivePanel*>();
        QVERIFY(live);
        // The live views are tabs of the workspace's central tab widgets, not squeezed into the dock.
        for (QWidget* view : {static_cast<QWidget*>(live->views()->trajectory2D()),
                              static_cast<QWidget*>(live->views()->trajectory3D()),
                              static_cast<QWidget*>(live->views()->signalPlots()),
                              static_cast<QWidget*>(live->views()->stanceFlags())}) {
            QWidget* tabs = view->parentWidget() ? view->parentWidget()->parentWidget() : nullptr;
            QVERIFY(qobject_cast<QTabWidget*>(tabs));
            QVERIFY(!live->isAncestorOf(view));
        }
        const double before = live->latency_s();
        auto* slider = window.findChild<QSlider*>(QStringLiteral("slider_window_half_s"));
        QVERIFY(slider);
        slider->setValue(slider->maximum());
        QVERIFY(live->latency_s() > before);  // the live estimator uses the workspace's parameters
        QCOMPARE(live->latency_s(), window.session()->parameters().window_half_s
                                        + window.session()->parameters().median_window_s / 2.0);
    }

    void togglingZaruChangesTheEstimate()
    {
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        QSignalSpy shown(&window, &MainWindow::resultShown);
        window.openRecording(path_);
        QVERIFY(shown.wait(30000));
        const std::shared_ptr<const Result> withZaru = window.session()->result();
        auto* zaru = window.findChild<QCheckBox*>(QStringLiteral("check_use_zaru"));
        QVERIFY(zaru && zaru->isChecked());
        zaru->click();
        QVERIFY(!window.session()->parameters().use_zaru);
        QTRY_VERIFY_WITH_TIMEOUT(window.session()->result() != withZaru && window.session()->result(), 30000);
        const Eigen::Vector3d a = withZaru->position_m.back(), b = window.session()->result()->position_m.back();
        QVERIFY((a - b).norm() > 1e-9);
    }

    void germanTranslationIsUsed()
    {
        QTranslator translator;
        QVERIFY2(translator.load(QStringLiteral(FOOTPATH_QM_DIR "/footpath_de.qm")), FOOTPATH_QM_DIR);
        QCoreApplication::installTranslator(&translator);
        AppSettings settings(QStringLiteral("FootpathTests"), QStringLiteral("tst_mainwindow"));
        MainWindow window(settings);
        const QString file = window.menuBar()->actions().first()->text();
        QCoreApplication::removeTranslator(&translator);
        QVERIFY2(file != QStringLiteral("&File") && !file.isEmpty(), qPrintable(file));
    }

private:
    QTemporaryDir dir_;
    QString path_;
    std::size_t samples_ = 0;
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
