#include "PlotInteraction.h"
#include "SignalPlots.h"

#include <QAction>
#include <QFile>
#include <QMenu>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>

#include <cmath>
#include <memory>

using namespace footpath;
using Row = SignalPlots::Row;

namespace {

constexpr double kRate_hz = 100.0;
constexpr std::size_t kSamples = 1000;  // 10 s

/// Known signals: acc x steps up by one each second (floor of the time), acc y is a tiny negative
/// (rounds to zero: must not read "-0.00"), acc z is gravity, gyro z follows time.
std::shared_ptr<const Recording> knownRecording()
{
    auto recording = std::make_shared<Recording>();
    for (std::size_t k = 0; k < kSamples; ++k) {
        ImuSample sample;
        sample.time_s = static_cast<double>(k) / kRate_hz;
        sample.acc_mps2 = Eigen::Vector3d(std::floor(sample.time_s), -1e-5, 9.81);
        sample.gyr_radps = Eigen::Vector3d(0.0, 0.0, sample.time_s / 10.0);
        recording->samples.push_back(sample);
    }
    return recording;
}

QCPAxisRect* accRow(const SignalPlots& plots) { return plots.axisRect(Row::Acceleration); }

QPointF pixelAt(const SignalPlots& plots, double time_s)
{
    const QCPAxisRect* rect = accRow(plots);
    return QPointF(rect->axis(QCPAxis::atBottom)->coordToPixel(time_s), rect->center().y());
}

void sendMouse(QWidget* target, QEvent::Type type, const QPointF& pos, Qt::MouseButton button,
               Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    const Qt::MouseButtons buttons = type == QEvent::MouseButtonRelease || type == QEvent::MouseMove ? Qt::NoButton : button;
    QMouseEvent event(type, pos, target->mapToGlobal(pos), button, buttons, modifiers);
    QApplication::sendEvent(target, &event);
}

void sendWheel(QWidget* target, const QPointF& pos, int notches, Qt::KeyboardModifiers modifiers)
{
    QWheelEvent event(pos, target->mapToGlobal(pos), QPoint(), QPoint(0, 120 * notches), Qt::NoButton, modifiers,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(target, &event);
}

bool isNegativeZero(const QString& label)
{
    static const QRegularExpression negativeZero(QStringLiteral("^-0([.,]0*)?$"));
    return negativeZero.match(label).hasMatch();
}

}  // namespace

class TestPlotInteraction : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<SignalPlots> plots_;

    void showPlots()
    {
        plots_ = std::make_unique<SignalPlots>();
        plots_->setRecording(knownRecording());
        plots_->resize(1000, 700);
        plots_->show();
        QVERIFY(QTest::qWaitForWindowExposed(plots_.get()));
        plots_->plot()->replot();
    }

private slots:
    void cleanup() { plots_.reset(); }

    void numbersNeverReadMinusZero()
    {
        QCOMPARE(formatPlotNumber(-0.0004, 3), QStringLiteral("0.000"));
        QCOMPARE(formatPlotNumber(-0.0, 0), QStringLiteral("0"));
        QCOMPARE(formatPlotNumber(-0.0006, 3), QStringLiteral("-0.001"));
        QCOMPARE(formatPlotNumber(-10.0, 0), QStringLiteral("-10"));
        // The tables' figures: the same, in the user's notation, a dash where there is no figure.
        QCOMPARE(formatFigure(-0.0004, 3), QStringLiteral("0.000"));
        QCOMPARE(formatFigure(-0.0006, 3), QStringLiteral("-0.001"));
        QCOMPARE(formatFigure(-0.004, 2, QLocale(QLocale::German)), QStringLiteral("0,00"));
        QCOMPARE(formatFigure(-1.25, 2, QLocale(QLocale::German)), QStringLiteral("-1,25"));
        QCOMPARE(formatFigure(std::nan(""), 2), QStringLiteral("\u2013"));
        QCOMPARE(decimalsForSpan(20.0), 2);
        QCOMPARE(decimalsForSpan(0.02), 5);
    }

    void hoverReadsTimeAndValuesAtThePointer()
    {
        showPlots();
        const QPointF at = pixelAt(*plots_, 2.5);
        sendMouse(plots_->plot(), QEvent::MouseMove, at, Qt::NoButton);
        const QString readout = plots_->interaction()->readoutText();
        const double shownTime = accRow(*plots_)->axis(QCPAxis::atBottom)->pixelToCoord(at.x());
        QVERIFY2(readout.contains(QStringLiteral("t = %1 s").arg(formatPlotNumber(shownTime, 3))), qPrintable(readout));
        QVERIFY2(readout.contains(QStringLiteral("x = 2.00 m/s²")), qPrintable(readout));
        QVERIFY2(readout.contains(QStringLiteral("y = 0.00 m/s²")), qPrintable(readout));  // -1e-5, not "-0.00"
        QVERIFY2(readout.contains(QStringLiteral("z = 9.81 m/s²")), qPrintable(readout));
        QVERIFY(!readout.contains(QStringLiteral("-0.0")));
        // The angular rate row speaks of its own curves.
        const QCPAxisRect* gyro = plots_->axisRect(Row::AngularRate);
        sendMouse(plots_->plot(), QEvent::MouseMove, QPointF(at.x(), gyro->center().y()), Qt::NoButton);
        QVERIFY2(plots_->interaction()->readoutText().contains(QStringLiteral("rad/s")), qPrintable(plots_->interaction()->readoutText()));
        QVERIFY(!plots_->interaction()->readoutText().contains(QStringLiteral("m/s²")));
        // Leaving the plot hides it.
        QEvent leave(QEvent::Leave);
        QApplication::sendEvent(plots_->plot(), &leave);
        QVERIFY(plots_->interaction()->readoutText().isEmpty());
    }

    void shiftClickSetsAMarkerAndTheReadoutMeasuresFromIt()
    {
        showPlots();
        QSignalSpy cursorMoves(plots_.get(), &SignalPlots::timeCursorMoved);
        const QPointF markerAt = pixelAt(*plots_, 2.5);
        sendMouse(plots_->plot(), QEvent::MouseButtonPress, markerAt, Qt::LeftButton, Qt::ShiftModifier);
        sendMouse(plots_->plot(), QEvent::MouseButtonRelease, markerAt, Qt::LeftButton, Qt::ShiftModifier);
        QVERIFY(plots_->interaction()->hasMarker());
        QCOMPARE(cursorMoves.count(), 0);  // Shift+click measures; it does not move the time cursor
        const QCPAxis* time = accRow(*plots_)->axis(QCPAxis::atBottom);
        QCOMPARE(plots_->interaction()->markerKey(), time->pixelToCoord(markerAt.x()));

        const QPointF hoverAt = pixelAt(*plots_, 6.5);
        sendMouse(plots_->plot(), QEvent::MouseMove, hoverAt, Qt::NoButton);
        const QString readout = plots_->interaction()->readoutText();
        const double deltaT = time->pixelToCoord(hoverAt.x()) - plots_->interaction()->markerKey();
        QVERIFY2(readout.contains(QStringLiteral("Δt = %1 s").arg(formatPlotNumber(deltaT, 3))), qPrintable(readout));
        QVERIFY2(readout.contains(QStringLiteral("x = 6.00 m/s² (Δ 4.00)")), qPrintable(readout));
        QVERIFY2(readout.contains(QStringLiteral("z = 9.81 m/s² (Δ 0.00)")), qPrintable(readout));

        QTest::keyClick(plots_.get(), Qt::Key_Escape);  // the view has the focus, not the plot
        QVERIFY(!plots_->interaction()->hasMarker());
        QVERIFY(!plots_->interaction()->readoutText().contains(QStringLiteral("Δ")));
        // A plain click still places the time cursor.
        sendMouse(plots_->plot(), QEvent::MouseButtonPress, hoverAt, Qt::LeftButton);
        sendMouse(plots_->plot(), QEvent::MouseButtonRelease, hoverAt, Qt::LeftButton);
        QCOMPARE(cursorMoves.count(), 1);
    }

    void ctrlWheelZoomsOnlyTheValueAxisAndDoubleClickRestores()
    {
        showPlots();
        plots_->setTimeRange(2.0, 6.0);
        QCPAxis* values = accRow(*plots_)->axis(QCPAxis::atLeft);
        const QCPRange valuesBefore = values->range();
        const QCPRange gyroBefore = plots_->axisRect(Row::AngularRate)->axis(QCPAxis::atLeft)->range();
        sendWheel(plots_->plot(), pixelAt(*plots_, 4.0), 2, Qt::ControlModifier);
        QVERIFY(values->range().size() < valuesBefore.size() * 0.8);
        QCOMPARE(plots_->timeRange().lower, 2.0);  // time untouched
        QCOMPARE(plots_->timeRange().upper, 6.0);
        QCOMPARE(plots_->axisRect(Row::AngularRate)->axis(QCPAxis::atLeft)->range(), gyroBefore);  // other rows too

        // The wheel over the value axis itself zooms it without Ctrl.
        const QCPRange zoomed = values->range();
        const QPointF overAxis(accRow(*plots_)->left() - 10, accRow(*plots_)->center().y());
        sendWheel(plots_->plot(), overAxis, -1, Qt::NoModifier);
        QVERIFY(values->range().size() > zoomed.size());
        QCOMPARE(plots_->timeRange().lower, 2.0);

        // A plain wheel in the row still zooms time only.
        const QCPRange valuesNow = values->range();
        sendWheel(plots_->plot(), pixelAt(*plots_, 4.0), 1, Qt::NoModifier);
        QVERIFY(plots_->timeRange().size() < 4.0);
        QCOMPARE(values->range(), valuesNow);

        sendMouse(plots_->plot(), QEvent::MouseButtonDblClick, pixelAt(*plots_, 4.0), Qt::LeftButton);
        QCOMPARE(values->range(), valuesBefore);
        QCOMPARE(plots_->timeRange().lower, 0.0);
        QCOMPARE(plots_->timeRange().upper, static_cast<double>(kSamples - 1) / kRate_hz);
    }

    void draggingTheValueAxisPansIt()
    {
        showPlots();
        QCPAxis* values = accRow(*plots_)->axis(QCPAxis::atLeft);
        const QCPRange before = values->range();
        const QCPRange timeBefore = plots_->timeRange();
        const QPointF from(accRow(*plots_)->left() - 10, accRow(*plots_)->center().y());
        sendMouse(plots_->plot(), QEvent::MouseButtonPress, from, Qt::LeftButton);
        QMouseEvent move(QEvent::MouseMove, from + QPointF(0, 30), plots_->plot()->mapToGlobal(from + QPointF(0, 30)),
                         Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(plots_->plot(), &move);
        sendMouse(plots_->plot(), QEvent::MouseButtonRelease, from + QPointF(0, 30), Qt::LeftButton);
        QVERIFY(values->range().lower > before.lower);  // dragged down: shows higher values
        QCOMPARE(values->range().size(), before.size());
        QCOMPARE(plots_->timeRange(), timeBefore);
    }

    void csvExportHoldsTheVisibleRangeOnly()
    {
        showPlots();
        plots_->setTimeRange(2.0, 3.0);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("visible.csv"));
        QVERIFY(plots_->interaction()->exportCsv(path));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
        const QStringList lines = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        const std::shared_ptr<const Recording> recording = knownRecording();
        int expected = 0;
        for (const ImuSample& sample : recording->samples)
            expected += sample.time_s >= 2.0 && sample.time_s <= 3.0;
        QCOMPARE(lines.size(), expected + 1);
        const QStringList header = lines.front().split(QLatin1Char(','));
        QCOMPARE(header.front(), QStringLiteral("Time (s)"));
        const qsizetype accX = header.indexOf(QStringLiteral("Acceleration (m/s²): x"));
        const qsizetype gyrZ = header.indexOf(QStringLiteral("Angular rate (rad/s): z"));
        QVERIFY2(accX > 0 && gyrZ > 0, qPrintable(lines.front()));
        for (qsizetype l = 1; l < lines.size(); ++l) {
            const QStringList cells = lines[l].split(QLatin1Char(','));
            QCOMPARE(cells.size(), header.size());
            const double time = cells.front().toDouble();
            QVERIFY(time >= 2.0 && time <= 3.0);
            QCOMPARE(cells[accX].toDouble(), std::floor(time));
            QVERIFY(std::abs(cells[gyrZ].toDouble() - time / 10.0) < 1e-9);
        }
    }

    void contextMenuOffersResetAndExports()
    {
        showPlots();
        std::unique_ptr<QMenu> menu(plots_->interaction()->createContextMenu(nullptr));
        for (const char* name : {"resetView", "clearMarker", "exportPng", "exportSvg", "exportPdf", "exportCsv"})
            QVERIFY2(menu->findChild<QAction*>(QLatin1String(name)) != nullptr, name);
        QVERIFY(!menu->findChild<QAction*>(QStringLiteral("clearMarker"))->isEnabled());  // no marker yet
        QTemporaryDir dir;
        QVERIFY(plots_->interaction()->exportPng(dir.filePath(QStringLiteral("plot.png"))));
        QVERIFY(plots_->interaction()->exportPdf(dir.filePath(QStringLiteral("plot.pdf"))));
        QVERIFY(QImage(dir.filePath(QStringLiteral("plot.png"))).width() >= plots_->plot()->width());
        QVERIFY(QFileInfo(dir.filePath(QStringLiteral("plot.pdf"))).size() > 1000);
    }

    void svgExportIsAVectorDrawingOfThePlot()
    {
        showPlots();
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("plot.svg"));
        QVERIFY(plots_->interaction()->exportSvg(path));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray svg = file.readAll();
        QVERIFY2(svg.startsWith("<?xml"), svg.left(80).constData());
        QVERIFY(svg.contains("<svg"));
        const QString viewBox = QStringLiteral("viewBox=\"0 0 %1 %2\"").arg(plots_->plot()->width()).arg(plots_->plot()->height());
        QVERIFY2(svg.contains(viewBox.toUtf8()), qPrintable(viewBox));
        // A drawing, not a picture in an SVG wrapper: a curve is one line through hundreds of samples (the
        // fixture's 1000), the axes' labels and units are text.
        QVERIFY(!svg.contains("<image"));
        qsizetype longestLine = 0;
        static const QRegularExpression lines(QStringLiteral("<(?:polyline|path)[^>]*(?:points|d)=\"([^\"]*)\""));
        for (QRegularExpressionMatchIterator it = lines.globalMatch(QString::fromUtf8(svg)); it.hasNext();)
            longestLine = std::max(longestLine, it.next().captured(1).split(QLatin1Char(' '), Qt::SkipEmptyParts).size());
        QVERIFY2(longestLine >= static_cast<qsizetype>(kSamples / 2), qPrintable(QString::number(longestLine)));
        for (const char* text : {">Acceleration</text>", ">(m/s²)</text>", ">Time (s)</text>"})
            QVERIFY2(svg.contains(text), text);
        // A folder that does not exist: a clear failure, not a claimed success.
        QVERIFY(!plots_->interaction()->exportSvg(dir.filePath(QStringLiteral("missing/plot.svg"))));
    }

    void ticksAreRoundAndNeverMinusZero()
    {
        showPlots();
        QCPAxis* values = accRow(*plots_)->axis(QCPAxis::atLeft);
        const auto labelsFor = [&](double lower, double upper) {
            values->setRange(lower, upper);
            plots_->plot()->replot();
            return values->tickVectorLabels();
        };
        const QVector<QString> tenths = labelsFor(-0.3, 0.3);
        QVERIFY(!tenths.isEmpty());
        for (const QString& label : tenths)
            QVERIFY2(!isNegativeZero(label), qPrintable(label));
        QVERIFY(tenths.contains(QStringLiteral("0.0")) || tenths.contains(QStringLiteral("0")));
        const QVector<QString> tens = labelsFor(0.0, 10.0);
        QVERIFY(!tens.contains(QStringLiteral("2.5")) && !tens.contains(QStringLiteral("7.5")));
        // A pressure axis spanning hundredths of a hPa: every label different.
        const QVector<QString> pressure = labelsFor(1013.243, 1013.268);
        QVERIFY(pressure.size() >= 2);
        for (qsizetype i = 1; i < pressure.size(); ++i)
            QVERIFY2(pressure[i] != pressure[i - 1], qPrintable(pressure[i]));
        // The time axes have the same ticker.
        QVERIFY(!qSharedPointerDynamicCast<ReadableTicker>(plots_->axisRect(Row::AngularRate)->axis(QCPAxis::atBottom)->ticker()).isNull());
    }
};

QTEST_MAIN(TestPlotInteraction)
#include "tst_plotinteraction.moc"
