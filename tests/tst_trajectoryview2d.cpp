#include "LegendChecks.h"
#include "PixelCurve.h"
#include "PlotInteraction.h"
#include "TrajectoryView2D.h"
#include "metrics/Evaluation.h"
#include "nav/Pipeline.h"
#include "sim/WalkSimulator.h"

#include <Eigen/Geometry>
#include <QElapsedTimer>
#include <QImage>
#include <QSignalSpy>
#include <QtTest>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

using namespace footpath;

namespace {

constexpr double kPi = 3.14159265358979323846;

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

double distanceToSegment(const QPointF& point, const QPointF& from, const QPointF& to)
{
    const QPointF segment = to - from;
    const double squared = QPointF::dotProduct(segment, segment);
    const double t =
        squared > 0.0 ? std::clamp(QPointF::dotProduct(point - from, segment) / squared, 0.0, 1.0) : 0.0;
    const QPointF off = point - (from + t * segment);
    return std::sqrt(QPointF::dotProduct(off, off));
}

int differingPixels(const QImage& a, const QImage& b)
{
    if (a.size() != b.size())
        return a.width() * a.height();
    int differing = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            differing += a.pixel(x, y) != b.pixel(x, y);
    return differing;
}

/// The 10 m x 5 m loop estimated by the real pipeline, computed once for all tests.
const SimulatedWalk& rectangleWalk()
{
    static const SimulatedWalk walk = simulateWalk(closedRectanglePath(10.0, 5.0), WalkSimulatorConfig());
    return walk;
}

const Result& rectangleResult()
{
    static const Result result = runPipeline(rectangleWalk().recording, Parameters()).result;
    return result;
}

/// A walk of the given length built directly (no simulation): laps of a 20 m x 10 m rectangle with
/// a speed that pulses like strides, drifting 0.3 m per lap so the laps do not overlap exactly.
Result longWalk(double duration_s, double rate_hz)
{
    Result result;
    const auto samples = static_cast<std::size_t>(duration_s * rate_hz);
    const double perimeter_m = 60.0;
    for (std::size_t k = 0; k < samples; ++k) {
        const double t = static_cast<double>(k) / rate_hz;
        const double s = 1.3 * t - 1.3 / (2.0 * kPi) * std::sin(2.0 * kPi * t);  // speed 0 .. 2.6 m/s
        const double lap = std::floor(s / perimeter_m), along = s - lap * perimeter_m;
        const double drift = 0.3 * lap;
        Eigen::Vector3d p;
        if (along < 20.0)
            p = {along, drift, 0.0};
        else if (along < 30.0)
            p = {20.0 + drift, along - 20.0, 0.0};
        else if (along < 50.0)
            p = {50.0 - along, 10.0 + drift, 0.0};
        else
            p = {-drift, 60.0 - along, 0.0};
        p.z() = 0.1 * std::max(0.0, std::sin(2.0 * kPi * t - kPi / 2.0));
        result.time_s.push_back(t);
        result.position_m.push_back(p);
        result.flags.stance.push_back(std::fmod(t, 1.0) < 0.3 ? 1 : 0);
    }
    for (std::size_t k = 0; k < samples; ++k) {
        const std::size_t a = k == 0 ? 0 : k - 1, b = std::min(k + 1, samples - 1);
        result.velocity_mps.push_back((result.position_m[b] - result.position_m[a]) * rate_hz / double(b - a));
    }
    for (std::size_t k = 0; k < samples; k += static_cast<std::size_t>(rate_hz)) {
        Step step;
        step.stanceStart_s = result.time_s[k];
        step.position_m = result.position_m[k];
        result.steps.push_back(step);
    }
    return result;
}

QCPGraph* graphNamed(QCustomPlot* plot, const QString& name)
{
    for (int i = 0; i < plot->graphCount(); ++i) {
        if (plot->graph(i)->name() == name)
            return plot->graph(i);
    }
    return nullptr;
}

QCPCurve* curveNamed(QCustomPlot* plot, const QString& name)
{
    for (int i = 0; i < plot->plottableCount(); ++i) {
        if (auto* curve = qobject_cast<QCPCurve*>(plot->plottable(i)); curve && curve->name() == name)
            return curve;
    }
    return nullptr;
}

QPoint toPixel(QCustomPlot* plot, const Eigen::Vector3d& position_m)
{
    return QPointF(plot->xAxis->coordToPixel(position_m.x()), plot->yAxis->coordToPixel(position_m.y())).toPoint();
}

/// Index of the sample with the greatest speed: samples there are far apart, so a click picks one.
std::size_t fastestSample(const Result& result)
{
    std::size_t fastest = 0;
    for (std::size_t k = 0; k < result.velocity_mps.size(); ++k) {
        if (result.velocity_mps[k].norm() > result.velocity_mps[fastest].norm())
            fastest = k;
    }
    return fastest;
}

double metresPerPixelRatio(QCustomPlot* plot)
{
    const double xPerPixel = plot->xAxis->range().size() / plot->axisRect()->width();
    const double yPerPixel = plot->yAxis->range().size() / plot->axisRect()->height();
    return xPerPixel / yPerPixel;
}

/// The view's stance markers (the graph named "Stance") once it has shown result at 600 x 400,
/// or nullptr.
QCPGraph* stanceGraphShowing(TrajectoryView2D& view, const Result& result)
{
    view.resize(600, 400);
    view.showResult(result);
    view.grab();
    for (int g = 0; g < view.plot()->graphCount(); ++g)
        if (view.plot()->graph(g)->name() == QStringLiteral("Stance"))
            return view.plot()->graph(g);
    return nullptr;
}

}  // namespace

class TestTrajectoryView2D : public QObject {
    Q_OBJECT
private slots:
    void pixelMapIsTheAxesMap()
    {
        // The multiply-add map agrees with QCustomPlot's own to far below a pixel: on plain,
        // reversed, swapped (vertical key) and logarithmic axes.
        QCustomPlot plot;
        plot.resize(640, 480);
        plot.xAxis->setRange(-12.5, 87.25);
        plot.yAxis->setRange(1e-3, 40.0);
        plot.replot();  // lays out the axis rect
        QCPGraph* graph = plot.addGraph();
        QCPGraph* swapped = plot.addGraph(plot.yAxis, plot.xAxis);
        for (const bool reversed : {false, true})
            for (const bool logarithmic : {false, true}) {
                plot.xAxis->setRangeReversed(reversed);
                plot.yAxis->setScaleType(logarithmic ? QCPAxis::stLogarithmic : QCPAxis::stLinear);
                for (QCPGraph* g : {graph, swapped}) {
                    const PixelMap map(g->keyAxis(), g->valueAxis());
                    for (const double key : {-12.5, 0.0, 3.3, 87.25, 200.0})
                        for (const double value : {1e-3, 0.5, 17.0, 40.0}) {
                            const double k = g == graph ? key : value, v = g == graph ? value : key;
                            const QPointF expected = g->coordsToPixels(k, v), mapped = map(k, v);
                            QVERIFY2(std::abs(expected.x() - mapped.x()) < 1e-9 && std::abs(expected.y() - mapped.y()) < 1e-9,
                                     qPrintable(QStringLiteral("%1 %2 reversed %3 log %4").arg(k).arg(v).arg(reversed).arg(logarithmic)));
                        }
                }
            }
    }

    void simplifiedLineStaysWithinTheToleranceOfEveryPoint()
    {
        // A walk in pixels: rests that jitter on a pixel, swings along slightly bent lines, turns,
        // and a stretch to and fro on one line. Every point lies within the tolerance of the
        // segment drawn between the kept points around it; the straight runs keep few points.
        std::vector<QPointF> points;
        QPointF at(100.0, 100.0);
        double heading = 0.0;
        std::uint32_t seed = 12345;
        const auto noise = [&seed](double amplitude) {
            seed = seed * 1664525u + 1013904223u;
            return amplitude * (static_cast<double>(seed >> 8) / double(1u << 24) - 0.5);
        };
        for (int stride = 0; stride < 200; ++stride) {
            for (int k = 0; k < 40; ++k)
                points.push_back(at + QPointF(noise(0.3), noise(0.3)));
            const double length = stride % 2 == 0 ? 6.0 + noise(4.0) : 40.0 + noise(30.0);
            const double bend = stride % 2 == 0 ? noise(0.6) : noise(12.0);  // within a pixel, or a curve
            for (int k = 1; k <= 60; ++k) {
                const double t = k / 60.0;
                const QPointF along(std::cos(heading), std::sin(heading)), across(-along.y(), along.x());
                points.push_back(at + t * length * along + 4.0 * t * (1.0 - t) * bend * across);
            }
            at = points.back();
            heading += stride % 25 == 24 ? 1.6 : noise(0.1);
        }
        for (int lap = 0; lap < 4; ++lap)
            for (int k = 0; k <= 50; ++k)
                points.push_back(at + QPointF(lap % 2 == 0 ? 0.4 * k : 20.0 - 0.4 * k, 0.0));
        for (const double tolerance : {1.0, 3.0}) {
            std::vector<std::size_t> kept;
            StraightRunSimplifier runs(tolerance);
            const auto keep = [&kept](const QPointF&, std::size_t index) { kept.push_back(index); };
            for (std::size_t k = 0; k < points.size(); ++k)
                runs.add(points[k], k, keep);
            runs.finish(keep);
            QCOMPARE(kept.front(), std::size_t(0));
            QCOMPARE(kept.back(), points.size() - 1);
            QVERIFY(std::is_sorted(kept.begin(), kept.end()));
            QVERIFY(std::adjacent_find(kept.begin(), kept.end()) == kept.end());
            double farthest = 0.0;
            for (std::size_t s = 0; s + 1 < kept.size(); ++s)
                for (std::size_t k = kept[s]; k <= kept[s + 1]; ++k)
                    farthest = std::max(farthest, distanceToSegment(points[k], points[kept[s]], points[kept[s + 1]]));
            qInfo("tolerance %.0f px: %zu of %zu points kept, farthest %.3f px", tolerance, kept.size(), points.size(),
                  farthest);
            QVERIFY2(farthest <= tolerance + 1e-9, qPrintable(QString::number(farthest)));
            QVERIFY2(kept.size() < points.size() / 10, qPrintable(QString::number(kept.size())));
        }
        // Straight: the ends alone. Gaps (NaN) stay, each piece with its own ends.
        QVector<QPointF> line;
        for (int k = 0; k < 1000; ++k)
            line.append(QPointF(0.37 * k, 10.0 + 0.11 * k));
        QCOMPARE(pixelSimplified(line), (QVector<QPointF>{line.front(), line.back()}));
        const QPointF gap(qQNaN(), qQNaN());
        QVector<QPointF> pieces = line;
        pieces.insert(500, gap);
        const QVector<QPointF> kept = pixelSimplified(pieces);
        QCOMPARE(kept.size(), 5);
        QCOMPARE(kept[0], line[0]);
        QCOMPARE(kept[1], line[499]);
        QVERIFY(std::isnan(kept[2].x()));
        QCOMPARE(kept[3], line[500]);
        QCOMPARE(kept[4], line.back());
    }

    void stampedMarkersLookLikeDrawnOnes()
    {
        // Each stamped marker covers the pixels the shape drawn itself covers: the same ink, in
        // the same place to a pixel, for the view's marker styles.
        const std::vector<QCPScatterStyle> styles{
            QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(230, 120, 20), 5),
            QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(QColor(40, 40, 40), 1.2), Qt::white, 6),
            QCPScatterStyle(QCPScatterStyle::ssCross, QPen(Qt::red, 2.0), Qt::NoBrush, 10)};
        const std::vector<QPointF> points{{1.0, 1.0}, {2.37, 4.11}, {7.5, 2.25}, {5.05, 8.8}};
        for (const QCPScatterStyle& style : styles) {
            std::array<QImage, 2> images, scaledExports;
            for (int stamped = 0; stamped < 2; ++stamped) {
                QCustomPlot plot;
                plot.resize(320, 240);
                plot.xAxis->setRange(0.0, 10.0);
                plot.yAxis->setRange(0.0, 10.0);
                QCPGraph* graph = stamped ? new StampedMarkerGraph(plot.xAxis, plot.yAxis) : plot.addGraph();
                graph->setLineStyle(QCPGraph::lsNone);
                graph->setScatterStyle(style);
                for (const QPointF& p : points)
                    graph->addData(p.x(), p.y());
                plot.replot();
                images[static_cast<std::size_t>(stamped)] = plot.toPixmap(320, 240).toImage();
                // A PNG exported at twice the size is drawn scaled: the shapes, not copies.
                scaledExports[static_cast<std::size_t>(stamped)] = plot.toPixmap(320, 240, 2.0).toImage();
                if (stamped) {
                    for (const QPointF& p : points) {
                        const QPointF centre = graph->coordsToPixels(p.x(), p.y());
                        const auto ink = [&centre](const QImage& image) {
                            double sum = 0.0, x = 0.0, y = 0.0;
                            for (int dy = -9; dy <= 9; ++dy)
                                for (int dx = -9; dx <= 9; ++dx) {
                                    const QPoint at(static_cast<int>(centre.x()) + dx, static_cast<int>(centre.y()) + dy);
                                    const double dark = 255.0 - qGray(image.pixel(at));
                                    sum += dark;
                                    x += dark * at.x();
                                    y += dark * at.y();
                                }
                            return std::array<double, 3>{sum, x / sum, y / sum};
                        };
                        const auto drawn = ink(images[0]), copied = ink(images[1]);
                        const QString where = QStringLiteral("shape %1 at %2, %3").arg(int(style.shape())).arg(p.x()).arg(p.y());
                        QVERIFY2(drawn[0] > 0.0 && std::abs(copied[0] - drawn[0]) < 0.25 * drawn[0], qPrintable(where));
                        const double offset = std::hypot(copied[1] - drawn[1], copied[2] - drawn[2]);
                        QVERIFY2(offset < 0.75, qPrintable(where + QStringLiteral(": %1 px off").arg(offset)));
                    }
                    QVERIFY(images[0] != images[1]);  // copies on whole pixels, not the shapes
                    QCOMPARE(scaledExports[1], scaledExports[0]);
                }
            }
        }
    }

    void drawsThePathWithoutOpenGl()
    {
        TrajectoryView2D view;
        view.resize(600, 400);
        const int emptyPixels = paintedPixels(view.grab().toImage());
        view.showResult(rectangleResult());
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
        view.setColouring(TrajectoryView2D::Colouring::Speed);
        view.setTimeCursor(1.0);
        QVERIFY(!view.grab().isNull());
        view.setResult(nullptr);
        QVERIFY(!view.grab().isNull());
    }

    void colouringModesChangeThePixels()
    {
        TrajectoryView2D view;
        view.resize(700, 450);
        view.setResult(std::make_shared<const Result>(rectangleResult()));
        const QImage plain = view.grab().toImage();
        view.setColouring(TrajectoryView2D::Colouring::Time);
        const QImage byTime = view.grab().toImage();
        view.setColouring(TrajectoryView2D::Colouring::Speed);
        const QImage bySpeed = view.grab().toImage();
        QCOMPARE(view.colouring(), TrajectoryView2D::Colouring::Speed);
        QVERIFY2(differingPixels(plain, byTime) > 2000, "the time colouring (and its scale) is not drawn");
        QVERIFY2(differingPixels(byTime, bySpeed) > 300, "speed and time colour the path alike");
        view.setColouring(TrajectoryView2D::Colouring::None);
        QCOMPARE(differingPixels(plain, view.grab().toImage()), 0);  // the colour scale leaves again
    }

    void colourScaleShowsOnlyWhenColouring()
    {
        TrajectoryView2D view;
        view.resize(600, 400);
        view.showResult(rectangleResult());
        const auto scales = [&view] { return view.plot()->plotLayout()->hasElement(0, 1); };
        QVERIFY(!scales());
        view.setColouring(TrajectoryView2D::Colouring::Speed);
        QVERIFY(scales());
        auto* scale = qobject_cast<QCPColorScale*>(view.plot()->plotLayout()->element(0, 1));
        QVERIFY(scale);
        QVERIFY(scale->axis()->label().contains("m/s"));
        QVERIFY(scale->dataRange().upper > 1.0);  // the simulated foot swings faster than 1 m/s
        view.setColouring(TrajectoryView2D::Colouring::Time);
        QVERIFY(scale->axis()->label().contains("(s)"));
        QCOMPARE(scale->dataRange().upper, rectangleResult().time_s.back());
    }

    void timeCursorMarkerSitsAtThePositionOfTheNearestTime()
    {
        const Result& result = rectangleResult();
        TrajectoryView2D view;
        view.resize(700, 450);
        view.showResult(result);
        const std::size_t k = fastestSample(result);
        // Just past sample k, nearer to it than to k + 1.
        view.setTimeCursor(result.time_s[k] + 0.3 * (result.time_s[k + 1] - result.time_s[k]));
        QCPGraph* cursor = graphNamed(view.plot(), "Time cursor");
        QVERIFY(cursor);
        QCOMPARE(cursor->data()->size(), 1);
        QCOMPARE(cursor->data()->at(0)->key, result.position_m[k].x());
        QCOMPARE(cursor->data()->at(0)->value, result.position_m[k].y());
        const QImage image = view.grab().toImage();
        const QColor centre = image.pixelColor(toPixel(view.plot(), result.position_m[k]));
        QVERIFY2(centre.red() > 200 && centre.green() > 180 && centre.blue() < 80,
                 qPrintable("no marker at the position: " + centre.name()));

        view.setTimeCursor(result.time_s.back() + 100.0);  // past the end: the last sample
        QCOMPARE(cursor->data()->at(0)->key, result.position_m.back().x());
        view.setTimeCursor(std::nan(""));
        QCOMPARE(cursor->data()->size(), 0);
    }

    void clickNearThePathEmitsTheTimeOfTheNearestSample()
    {
        const Result& result = rectangleResult();
        TrajectoryView2D view;
        view.resize(700, 450);
        view.showResult(result);
        (void)view.grab();  // lay out, so pixels map to metres as they will when clicked
        QSignalSpy moved(&view, &TrajectoryView2D::timeCursorMoved);
        const std::size_t k = fastestSample(result);
        const QPoint pixel = toPixel(view.plot(), result.position_m[k]) + QPoint(2, 1);

        QTest::mouseClick(view.plot(), Qt::LeftButton, Qt::NoModifier, pixel);
        QCOMPARE(moved.count(), 1);
        const Eigen::Vector2d clicked(view.plot()->xAxis->pixelToCoord(pixel.x()), view.plot()->yAxis->pixelToCoord(pixel.y()));
        const auto nearest = std::min_element(result.position_m.cbegin(), result.position_m.cend(),
                                              [&clicked](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
                                                  return (a.head<2>() - clicked).norm() < (b.head<2>() - clicked).norm();
                                              });
        const double expected = result.time_s[static_cast<std::size_t>(nearest - result.position_m.cbegin())];
        QCOMPARE(moved.at(0).at(0).toDouble(), expected);
        QVERIFY(std::abs(expected - result.time_s[k]) < 0.05);
        QCOMPARE(view.timeCursor(), expected);  // the view moves its own marker too

        QTest::mouseClick(view.plot(), Qt::LeftButton, Qt::NoModifier, QPoint(view.width() - 3, view.height() - 3));
        QCOMPARE(moved.count(), 1);  // far from the path: nothing
        QTest::mousePress(view.plot(), Qt::LeftButton, Qt::NoModifier, pixel);
        QTest::mouseRelease(view.plot(), Qt::LeftButton, Qt::NoModifier, pixel + QPoint(40, 0));
        QCOMPARE(moved.count(), 1);  // a drag pans, it does not move the cursor
    }

    void hoverReadsTheNearestSampleAndShiftClickMeasuresFromIt()
    {
        const Result& result = rectangleResult();
        TrajectoryView2D view;
        view.resize(700, 450);
        view.showResult(result);
        (void)view.grab();
        PlotInteraction& interaction = *view.interaction();
        const auto nearestTo = [&](const QPoint& pixel) {
            const Eigen::Vector2d at(view.plot()->xAxis->pixelToCoord(pixel.x()), view.plot()->yAxis->pixelToCoord(pixel.y()));
            const auto nearest = std::min_element(result.position_m.cbegin(), result.position_m.cend(),
                                                  [&at](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
                                                      return (a.head<2>() - at).norm() < (b.head<2>() - at).norm();
                                                  });
            return static_cast<std::size_t>(nearest - result.position_m.cbegin());
        };
        const std::size_t k = fastestSample(result);
        const QPoint first = toPixel(view.plot(), result.position_m[k]);
        interaction.probeAt(first);
        const std::size_t a = nearestTo(first);
        const QString readout = interaction.readoutText();
        QVERIFY2(readout.contains(QStringLiteral("x = %1 m").arg(formatPlotNumber(result.position_m[a].x(), 2))), qPrintable(readout));
        QVERIFY2(readout.contains(QStringLiteral("y = %1 m").arg(formatPlotNumber(result.position_m[a].y(), 2))), qPrintable(readout));
        QVERIFY2(readout.contains(QStringLiteral("t = %1 s").arg(formatPlotNumber(result.time_s[a], 3))), qPrintable(readout));

        QSignalSpy moved(&view, &TrajectoryView2D::timeCursorMoved);
        QTest::mouseClick(view.plot(), Qt::LeftButton, Qt::ShiftModifier, first);
        QVERIFY(interaction.hasMarker());
        QCOMPARE(moved.count(), 0);  // Shift+click measures; the time cursor stays
        const QPoint second = toPixel(view.plot(), result.position_m[k / 2]);
        interaction.probeAt(second);
        const std::size_t b = nearestTo(second);
        const QString measured = interaction.readoutText();
        QVERIFY2(measured.contains(QStringLiteral("Δt = %1 s").arg(formatPlotNumber(result.time_s[b] - result.time_s[a], 3))),
                 qPrintable(measured));
        const double distance = (result.position_m[b] - result.position_m[a]).head<2>().norm();
        QVERIFY2(measured.contains(QStringLiteral("distance %1 m").arg(formatPlotNumber(distance, 2))), qPrintable(measured));

        interaction.probeAt(QPointF(view.width() - 3, 3));  // far from the path
        QVERIFY(interaction.readoutText().isEmpty());
    }

    void csvExportHoldsThePathInView()
    {
        const Result& result = rectangleResult();
        TrajectoryView2D view;
        view.resize(700, 450);
        view.showResult(result);
        (void)view.grab();
        const QStringList all = view.interaction()->visibleDataCsv().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(all.front(), QStringLiteral("time_s,x_m,y_m,z_m"));
        QCOMPARE(static_cast<std::size_t>(all.size() - 1), result.position_m.size());  // fitted: every sample in view
        view.plot()->xAxis->setRange(-1.0, 1.0);  // the start corner only
        const QStringList corner = view.interaction()->visibleDataCsv().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QVERIFY(corner.size() > 1 && corner.size() < all.size());
        for (qsizetype l = 1; l < corner.size(); ++l)
            QVERIFY(std::abs(corner[l].split(QLatin1Char(','))[1].toDouble()) <= 1.0);
    }

    void stanceMarkersShowOnlyWhereTheyAreApart()
    {
        // 1500 strides of 1.4 m along 2.1 km: seen whole, the markers would be a pixel apart and
        // hide the path; zoomed in to 30 m they are 30 px apart and shown (and listed) again.
        Result result;
        for (int k = 0; k <= 1500; ++k) {
            const Eigen::Vector3d at(1.4 * k, 0.1 * std::sin(0.01 * k), 0.0);
            result.time_s.push_back(1.1 * k);
            result.position_m.push_back(at);
            Step step;
            step.position_m = at;
            step.strideLength_m = k == 0 ? 0.0 : 1.4;
            result.steps.push_back(step);
        }
        TrajectoryView2D view;
        QCPGraph* stances = stanceGraphShowing(view, result);
        QVERIFY(stances);
        QCOMPARE(stances->data()->size(), 1501);
        QVERIFY(!stances->visible());
        QVERIFY(!view.plot()->legend->hasItemWithPlottable(stances));

        // The next result is fitted before its first replot decides: no stale scale.
        view.showResult(rectangleResult());
        view.plot()->replot();
        QVERIFY(stances->visible());
        view.showResult(result);
        view.plot()->replot();
        QVERIFY(!stances->visible());

        view.plot()->xAxis->setRange(0.0, 30.0);
        view.plot()->yAxis->setRange(-10.0, 10.0);
        view.plot()->replot();
        QVERIFY(stances->visible());
        QVERIFY(view.plot()->legend->hasItemWithPlottable(stances));

        view.showResult(rectangleResult());  // a short walk seen whole: its markers are shown
        view.plot()->replot();
        QVERIFY(stances->visible());
    }

    void stanceMarkersOfLapsAreSpacedInWalkingOrder()
    {
        // Twenty 300 m lines 8 m apart, walked to and fro, a stance every 1.4 m: a pixel or two
        // apart seen whole. Taken in x order, as the graph keeps them, neighbours would lie on
        // adjacent lines, 8 m (over 10 px) apart, and the dots would cover the path.
        Result result;
        for (int line = 0; line < 20; ++line)
            for (int i = 0; i <= 214; ++i) {
                const double along = 1.4 * (line % 2 == 0 ? i : 214 - i) + 0.01 * line;
                Step step;
                step.position_m = Eigen::Vector3d(along, 8.0 * line, 0.0);
                step.strideLength_m = 1.4;
                result.time_s.push_back(1.1 * double(result.steps.size()));
                result.position_m.push_back(step.position_m);
                result.steps.push_back(step);
            }
        TrajectoryView2D view;
        QCPGraph* stances = stanceGraphShowing(view, result);
        QVERIFY(stances);
        QVERIFY(!stances->visible());
    }

    void referenceOverlayIsPresentOnlyWhenGiven()
    {
        const Result& result = rectangleResult();
        TrajectoryView2D view;
        view.resize(700, 450);
        view.showResult(result);
        QCPCurve* reference = curveNamed(view.plot(), "Reference");
        QVERIFY(reference);
        QCOMPARE(reference->data()->size(), 0);
        QVERIFY(!view.plot()->legend->hasItemWithPlottable(reference));
        const QImage without = view.grab().toImage();

        // Shift the truth so the overlay cannot hide under the path.
        std::vector<Eigen::Vector3d> shifted = rectangleWalk().truePosition_m;
        for (Eigen::Vector3d& p : shifted)
            p += Eigen::Vector3d(0.0, -0.5, 0.0);
        view.setReference(shifted);
        QCOMPARE(reference->data()->size(), static_cast<int>(shifted.size()));
        QVERIFY(view.plot()->legend->hasItemWithPlottable(reference));
        QCOMPARE(reference->pen().style(), Qt::DashLine);
        QVERIFY(differingPixels(without, view.grab().toImage()) > 500);

        view.setReference({});
        QCOMPARE(reference->data()->size(), 0);
        QVERIFY(!view.plot()->legend->hasItemWithPlottable(reference));
    }

    void legendEntriesAreNeverClipped()
    {
        // The path's column is what the legend has: with the colour scale beside it, less than the
        // view's width (wrapping to the whole width clipped "Foot path" to "Foot patl").
        const Result& result = rectangleResult();
        for (const auto colouring : {TrajectoryView2D::Colouring::None, TrajectoryView2D::Colouring::Speed}) {
            for (int width = 240; width <= 620; width += 19) {
                TrajectoryView2D view;
                view.resize(width, 420);
                view.show();
                QVERIFY(QTest::qWaitForWindowExposed(&view));
                view.showResult(result);
                view.setReference(rectangleWalk().truePosition_m);
                view.setColouring(colouring);
                view.plot()->replot();
                const QString problem = legendProblem(view.plot(), view.plot()->legend);
                QVERIFY2(problem.isEmpty(), qPrintable(QStringLiteral("%1 px: %2").arg(width).arg(problem)));
            }
        }
    }

    void alignedReferenceAgreesWithTheArmse()
    {
        // A reference in another frame: turned 40 degrees and shifted, as a VICON room would be.
        const Result& result = rectangleResult();
        const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        std::vector<Eigen::Vector3d> foreign;
        for (const Eigen::Vector3d& p : rectangleWalk().truePosition_m)
            foreign.push_back(turn * p + Eigen::Vector3d(3.0, -2.0, 0.5));

        const std::vector<Eigen::Vector3d> aligned = alignReferenceToEstimate(foreign, result.position_m);
        QCOMPARE(aligned.size(), foreign.size());
        QVERIFY((aligned.front() - result.position_m.front()).norm() < 1e-12);
        double sum = 0.0;
        for (std::size_t k = 0; k < aligned.size(); ++k)
            sum += (aligned[k] - result.position_m[k]).head<2>().norm() / std::sqrt(2.0);
        const double overlayError = sum / static_cast<double>(aligned.size());
        const ArmseResult armse = computeArmse(result.position_m, foreign);
        QVERIFY2(std::abs(overlayError - armse.armse2d_m) < 1e-9,
                 qPrintable(QString("%1 vs %2").arg(overlayError).arg(armse.armse2d_m)));
        QVERIFY(armse.armse2d_m < 0.5);  // the overlay really lies on the path, not just consistently off

        foreign.pop_back();
        QVERIFY(alignReferenceToEstimate(foreign, result.position_m).empty());
    }

    void equalAspectHoldsAfterResize_data()
    {
        QTest::addColumn<QSize>("size");
        QTest::addColumn<int>("colouring");
        QTest::newRow("wide") << QSize(900, 300) << int(TrajectoryView2D::Colouring::None);
        QTest::newRow("tall") << QSize(300, 800) << int(TrajectoryView2D::Colouring::None);
        QTest::newRow("tall with colour scale") << QSize(350, 800) << int(TrajectoryView2D::Colouring::Speed);
        QTest::newRow("small with colour scale") << QSize(260, 220) << int(TrajectoryView2D::Colouring::Time);
    }

    void equalAspectHoldsAfterResize()
    {
        QFETCH(QSize, size);
        QFETCH(int, colouring);
        TrajectoryView2D view;
        view.resize(600, 400);
        view.showResult(rectangleResult());
        view.setColouring(static_cast<TrajectoryView2D::Colouring>(colouring));
        (void)view.grab();
        view.resize(size);
        (void)view.grab();
        const double ratio = metresPerPixelRatio(view.plot());
        QVERIFY2(std::abs(ratio - 1.0) < 0.01, qPrintable(QString("x/y metres per pixel %1").arg(ratio)));
        for (const Eigen::Vector3d& p : rectangleResult().position_m) {
            QVERIFY(view.plot()->xAxis->range().contains(p.x()));
            QVERIFY(view.plot()->yAxis->range().contains(p.y()));
        }
    }

    void userZoomSurvivesResizeWithEqualAspect()
    {
        TrajectoryView2D view;
        view.resize(600, 400);
        view.showResult(rectangleResult());
        (void)view.grab();
        const double fittedWidth = view.plot()->xAxis->range().size();
        QWheelEvent wheel(QPointF(300, 200), view.plot()->mapToGlobal(QPointF(300, 200)), QPoint(), QPoint(0, 240),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(view.plot(), &wheel);
        (void)view.grab();
        const double zoomedWidth = view.plot()->xAxis->range().size();
        QVERIFY(zoomedWidth < 0.9 * fittedWidth);
        view.resize(640, 500);
        (void)view.grab();
        QVERIFY(std::abs(metresPerPixelRatio(view.plot()) - 1.0) < 0.01);
        QVERIFY2(view.plot()->xAxis->range().size() < 0.95 * fittedWidth, "resizing undid the user's zoom");
    }

    void followingAGrowingPathKeepsTheUsersZoom()
    {
        TrajectoryView2D view;
        view.resize(600, 400);
        const Result walk = longWalk(60.0, 100.0);
        const auto firstSeconds = [&](std::size_t samples) {
            Result part;
            part.time_s.assign(walk.time_s.begin(), walk.time_s.begin() + std::ptrdiff_t(samples));
            part.position_m.assign(walk.position_m.begin(), walk.position_m.begin() + std::ptrdiff_t(samples));
            return std::make_shared<const Result>(part);
        };
        view.followResult(firstSeconds(500));
        (void)view.grab();
        view.followResult(firstSeconds(3000));  // untouched: the view follows the path
        (void)view.grab();
        const Eigen::Vector3d newest = walk.position_m[2999];
        QVERIFY(view.plot()->xAxis->range().contains(newest.x()) && view.plot()->yAxis->range().contains(newest.y()));

        QWheelEvent wheel(QPointF(300, 200), view.plot()->mapToGlobal(QPointF(300, 200)), QPoint(), QPoint(0, 480),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(view.plot(), &wheel);
        (void)view.grab();
        const QCPRange zoomed = view.plot()->xAxis->range();
        view.followResult(firstSeconds(6000));
        (void)view.grab();
        const QCPRange kept = view.plot()->xAxis->range();  // the user's zoom stays while the path grows
        QVERIFY(std::abs(kept.lower - zoomed.lower) < 1e-9 && std::abs(kept.upper - zoomed.upper) < 1e-9);

        QMouseEvent doubleClick(QEvent::MouseButtonDblClick, QPointF(300, 200), view.plot()->mapToGlobal(QPointF(300, 200)),
                                Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(view.plot(), &doubleClick);
        view.followResult(firstSeconds(6000));
        (void)view.grab();
        QVERIFY2(view.plot()->xAxis->range().size() > 1.5 * zoomed.size(), "a double-click should fit and follow again");
    }

    void ghostStaysUnderTheOverlays_data()
    {
        QTest::addColumn<bool>("overlaysFirst");
        QTest::newRow("overlays, then a ghost") << true;
        QTest::newRow("a ghost, then overlays") << false;
    }
    void ghostStaysUnderTheOverlays()
    {
        // The ghost's opaque line must not hide the other foot's or a compared run's path,
        // whichever of them the window hands the view first.
        QFETCH(bool, overlaysFirst);
        TrajectoryView2D view;
        view.setResult(std::make_shared<const Result>(rectangleResult()));
        const std::vector<Eigen::Vector3d> line{{0.0, 0.0, 0.0}, {10.0, 0.0, 0.0}};
        const std::vector<PathOverlay> overlays{PathOverlay{QStringLiteral("Right foot"), Qt::red, line}};
        if (overlaysFirst)
            view.setOverlays(overlays);
        view.setGhostPath(line);
        if (!overlaysFirst)
            view.setOverlays(overlays);
        QCOMPARE(view.overlayCurves().size(), std::size_t(1));
        QVERIFY(view.ghostCurve());
        const int ghost = view.ghostCurve()->layer()->index();
        QVERIFY(ghost < view.overlayCurves().front()->layer()->index());
        QVERIFY(view.overlayCurves().front()->layer()->index() < view.plot()->layer(QStringLiteral("main"))->index());
    }

    void ghostOfManyLapsIsOneEvenGrey()
    {
        // The ghost is drawn as quick line segments in an opaque grey: where its laps (and its
        // segments' ends) overlap it stays the same faint grey a translucent pen left on white.
        TrajectoryView2D view;
        view.resize(600, 500);
        view.setResult(std::make_shared<const Result>(rectangleResult()));
        std::vector<Eigen::Vector3d> laps;
        for (int lap = 0; lap < 6; ++lap)
            for (int k = 0; k <= 100; ++k) {
                const double x = lap % 2 == 0 ? 0.1 * k : 10.0 - 0.1 * k;  // to and fro on one line
                laps.emplace_back(x, 2.5, 0.0);
            }
        view.setGhostPath(laps);
        QCOMPARE(view.ghostCurve()->pen().color().alpha(), 255);
        const QImage image = view.grab().toImage();
        const QCustomPlot* plot = view.plot();
        const int y = static_cast<int>(std::lround(plot->yAxis->coordToPixel(2.5)));
        int checked = 0;
        for (double x = 1.0; x < 9.0; x += 0.5) {
            const QColor colour = image.pixelColor(static_cast<int>(std::lround(plot->xAxis->coordToPixel(x))), y);
            if (colour == Qt::white || colour.red() != colour.green() || colour.green() != colour.blue())
                continue;  // the path or a marker crosses the ghost here
            QVERIFY2(colour.red() >= 195, qPrintable(QString("x %1 m: grey %2").arg(x).arg(colour.red())));
            ++checked;
        }
        QVERIFY(checked > 5);
    }

    void thirtyMinutePathRedrawsWellUnderHalfASecond()
    {
        const Result walk = longWalk(30.0 * 60.0, 100.0);
        TrajectoryView2D view;
        view.resize(1000, 700);
        view.setResult(std::make_shared<const Result>(walk));
        view.setReference(walk.position_m);
        for (auto colouring : {TrajectoryView2D::Colouring::None, TrajectoryView2D::Colouring::Time,
                               TrajectoryView2D::Colouring::Speed}) {
            view.setColouring(colouring);
            qint64 fastest_ms = std::numeric_limits<qint64>::max();
            for (int attempt = 0; attempt < 3; ++attempt) {
                QElapsedTimer timer;
                timer.start();
                view.plot()->replot();
                fastest_ms = std::min(fastest_ms, timer.elapsed());
            }
            qInfo("180k samples, colouring %d: replot %lld ms", int(colouring), fastest_ms);
            QVERIFY2(fastest_ms < 250, qPrintable(QString("%1 ms").arg(fastest_ms)));
        }
        // Zoomed in, no two samples share a pixel and most segments lie outside the view.
        view.plot()->xAxis->scaleRange(0.05);
        view.plot()->yAxis->scaleRange(0.05);
        QElapsedTimer zoomed;
        zoomed.start();
        view.plot()->replot();
        qInfo("180k samples, zoomed in 20x: replot %lld ms", zoomed.elapsed());
        QVERIFY2(zoomed.elapsed() < 250, qPrintable(QString("%1 ms").arg(zoomed.elapsed())));
        QElapsedTimer timer;
        timer.start();
        view.setTimeCursor(600.0);  // its own layer: the path is not drawn again
        qInfo("time cursor move: %lld ms", timer.elapsed());
        QVERIFY(timer.elapsed() < 50);
    }
};

QTEST_MAIN(TestTrajectoryView2D)
#include "tst_trajectoryview2d.moc"
