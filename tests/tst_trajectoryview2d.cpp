#include "TrajectoryView2D.h"
#include "nav/Pipeline.h"
#include "sim/WalkSimulator.h"

#include <QImage>
#include <QtTest>

using namespace footpath;

namespace {

/// Pixels that differ from the background colour of the plot's corner.
int paintedPixels(const QImage& image)
{
    const QRgb background = image.pixel(image.width() - 5, image.height() / 2);
    int painted = 0;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2)
            painted += image.pixel(x, y) != background;
    return painted;
}

}  // namespace

class TestTrajectoryView2D : public QObject {
    Q_OBJECT
private slots:
    void drawsThePathWithoutOpenGl()
    {
        const SimulatedWalk walk = simulateWalk(closedRectanglePath(10.0, 5.0), WalkSimulatorConfig());
        const PipelineOutput output = runPipeline(walk.recording, Parameters());
        TrajectoryView2D view;
        view.resize(600, 400);
        const int emptyPixels = paintedPixels(view.grab().toImage());
        view.showResult(output.result);
        const int drawnPixels = paintedPixels(view.grab().toImage());
        QVERIFY2(drawnPixels > emptyPixels + 200, qPrintable(QString("%1 vs %2").arg(drawnPixels).arg(emptyPixels)));
        view.clear();  // the axes keep their range; the path and markers go
        QVERIFY(paintedPixels(view.grab().toImage()) < drawnPixels - 200);
    }

    void showsAnEmptyResultWithoutCrashing()
    {
        TrajectoryView2D view;
        view.resize(300, 200);
        view.showResult(Result());
        QVERIFY(!view.grab().isNull());
    }
};

QTEST_MAIN(TestTrajectoryView2D)
#include "tst_trajectoryview2d.moc"
