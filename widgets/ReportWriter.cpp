#include "ReportWriter.h"

#include "ComparisonTable.h"
#include "MotionLanes.h"
#include "PlotInteraction.h"
#include "SignalPlots.h"
#include "StanceFlagsPlot.h"
#include "SummaryPanel.h"
#include "TrajectoryView2D.h"
#include "TrajectoryView3D.h"
#include "WarningOverlay.h"
#include "metrics/Evaluation.h"
#include "nav/MethodSets.h"
#include "nav/Pipeline.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfo>
#include <QPdfWriter>
#include <QPicture>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace footpath {

namespace {

QString tr(const char* text)
{
    // lupdate files these strings under the namespace's context.
    return QCoreApplication::translate("footpath", text);
}

/// Lays text, tables and figures out down the pages of a QPdfWriter. Coordinates are in the
/// writer's device units; sizes are given in millimetres and converted once.
class PageComposer {
public:
    static constexpr int kRowsKeptWithHeading = 5;

    PageComposer(QPdfWriter& writer, QCPPainter& painter) : writer_(writer), painter_(painter)
    {
        unitsPerMm_ = writer.resolution() / 25.4;
        page_ = QRectF(QPointF(0, 0), QSizeF(writer.width(), writer.height()));
        y_ = 0.0;
    }

    double mm(double millimetres) const { return millimetres * unitsPerMm_; }
    double width() const { return page_.width(); }

    void newPage()
    {
        writer_.newPage();
        y_ = 0.0;
    }

    /// Starts a new page when less than `height` is left.
    void ensureRoom(double height)
    {
        if (y_ + height > page_.height())
            newPage();
    }

    void heading(const QString& text, double sizePt = 13.0)
    {
        ensureRoom(mm(12));
        y_ += mm(3);
        text_(text, sizePt, true);
        painter_.setPen(QPen(Qt::black, mm(0.3)));
        painter_.drawLine(QPointF(0, y_), QPointF(width(), y_));
        y_ += mm(2);
    }

    void paragraph(const QString& text, double sizePt = 9.0, bool bold = false) { text_(text, sizePt, bold); }

    /// Rows of cells; column widths as fractions of the page width. Bold cells start with '*'.
    void table(const QList<QStringList>& rows, const QList<double>& widths, double sizePt = 8.5, bool header = true)
    {
        QFont font = painter_.font();
        font.setPointSizeF(sizePt);
        const double lineHeight = QFontMetricsF(font, &writer_).height() * 1.35;
        for (int r = 0; r < rows.size(); ++r) {
            const double rowHeight = rowHeightFor(rows[r], widths, font, lineHeight, header && r == 0);
            if (y_ + rowHeight > page_.height()) {
                newPage();
                if (header && r > 0)
                    drawRow(rows.first(), widths, font, rowHeightFor(rows.first(), widths, font, lineHeight, true), true);
            }
            drawRow(rows[r], widths, font, rowHeight, header && r == 0);
        }
        y_ += mm(2);
    }

    /// Starts a new page unless the heading, the table's header and its first rows (up to
    /// kRowsKeptWithHeading) fit on this one: a heading and two rows at a page's foot, the rest on
    /// the next page, read as an orphan.
    void keepHeadingWithTable(const QList<QStringList>& rows, const QList<double>& widths, double sizePt = 8.5)
    {
        QFont font = painter_.font();
        font.setPointSizeF(sizePt);
        const double lineHeight = QFontMetricsF(font, &writer_).height() * 1.35;
        double height = mm(12);  // the heading's room, as heading() keeps it
        for (int r = 0; r < rows.size() && r <= kRowsKeptWithHeading; ++r)
            height += rowHeightFor(rows[r], widths, font, lineHeight, r == 0);
        ensureRoom(height);
    }

    /// A figure of the given height with a caption; draw() paints into the rectangle it is given.
    /// Where the page has less room left, the figure shrinks (width and height alike, so a map
    /// keeps its scale) down to minScale rather than leave the rest of the page empty.
    void figure(const QString& caption, double height, const std::function<void(const QRectF&)>& draw,
                double minScale = 0.65)
    {
        const double captionRoom = mm(8);
        const double room = page_.height() - y_ - captionRoom;
        const double scale = room >= height ? 1.0 : room >= minScale * height ? room / height : 1.0;
        ensureRoom(scale * height + captionRoom);
        const double w = scale * width();
        const QRectF target((width() - w) / 2.0, y_, w, scale * height);
        height *= scale;
        painter_.save();
        draw(target);
        painter_.restore();
        y_ += height + mm(1);
        text_(caption, 8.0, false, true);
        y_ += mm(3);
    }

private:
    void text_(const QString& text, double sizePt, bool bold, bool italic = false)
    {
        QFont font = painter_.font();
        font.setPointSizeF(sizePt);
        font.setBold(bold);
        font.setItalic(italic);
        painter_.setFont(font);
        painter_.setPen(Qt::black);
        const QRectF bounds = painter_.boundingRect(QRectF(0, y_, width(), page_.height()), Qt::TextWordWrap, text);
        ensureRoom(bounds.height());
        painter_.drawText(QRectF(0, y_, width(), bounds.height()), Qt::TextWordWrap, text);
        y_ += bounds.height() + mm(1);
    }

    /// Cells wrap instead of being cut: the row is as high as its tallest cell.
    double rowHeightFor(const QStringList& cells, const QList<double>& widths, QFont font, double lineHeight,
                        bool header)
    {
        double height = lineHeight;
        for (int c = 0; c < cells.size() && c < widths.size(); ++c) {
            font.setBold(header || cells[c].startsWith(QLatin1Char('*')));
            painter_.setFont(font);
            const QRectF bounds = painter_.boundingRect(QRectF(0, 0, widths[c] * width() - mm(2), page_.height()),
                                                        Qt::TextWordWrap, cellText(cells[c]));
            height = std::max(height, bounds.height() + lineHeight * 0.35);
        }
        return height;
    }

    static QString cellText(const QString& cell) { return cell.startsWith(QLatin1Char('*')) ? cell.mid(1) : cell; }

    void drawRow(const QStringList& cells, const QList<double>& widths, QFont font, double rowHeight, bool header)
    {
        double x = 0.0;
        if (header) {
            painter_.fillRect(QRectF(0, y_, width(), rowHeight), QColor(225, 225, 225));
        }
        for (int c = 0; c < cells.size() && c < widths.size(); ++c) {
            QString cell = cells[c];
            const bool bold = header || cell.startsWith(QLatin1Char('*'));
            if (cell.startsWith(QLatin1Char('*')))
                cell.remove(0, 1);
            font.setBold(bold);
            painter_.setFont(font);
            painter_.setPen(Qt::black);
            const double w = widths[c] * width();
            painter_.drawText(QRectF(x + mm(1), y_, w - mm(2), rowHeight),
                              Qt::AlignVCenter | Qt::AlignLeft | Qt::TextWordWrap, cell);
            x += w;
        }
        painter_.setPen(QPen(QColor(190, 190, 190), mm(0.15)));
        painter_.drawLine(QPointF(0, y_ + rowHeight), QPointF(width(), y_ + rowHeight));
        y_ += rowHeight;
    }

    QPdfWriter& writer_;
    QCPPainter& painter_;
    QRectF page_;
    double unitsPerMm_ = 1.0;
    double y_ = 0.0;
};

/// Records a drawing at screen resolution into a QPicture and replays it scaled into the target:
/// still vectors and real text, and fonts keep their size relative to the figure (drawn straight
/// onto the 300 dpi writer they would resolve at 300 dpi and come out twice too large).
void drawScaled(QPainter& painter, const QRectF& target, int width, const std::function<void(QPainter&, QSize)>& draw)
{
    const QSize size(width, int(width * target.height() / target.width()));
    QPicture picture;
    {
        QCPPainter recorder(&picture);
        recorder.setMode(QCPPainter::pmVectorized);
        recorder.setMode(QCPPainter::pmNoCaching);
        draw(recorder, size);
    }
    // Replaying a QPicture already scales it from its own resolution to the device's.
    const double replayScale = double(painter.device()->logicalDpiX()) / picture.logicalDpiX();
    painter.translate(target.topLeft());
    painter.scale(target.width() / size.width() / replayScale, target.height() / size.height() / replayScale);
    painter.drawPicture(0, 0, picture);
}

void drawPlot(QPainter& painter, QCustomPlot* plot, const QRectF& target, int width = 760)
{
    useReadableTicks(plot);  // 1-2-5 steps, no "-0": the report's plots read like the workspace's
    drawScaled(painter, target, width, [plot](QPainter& recorder, QSize size) {
        // Laid out at the drawn size first: a legend wraps and the ticks are counted there, not at a
        // hidden widget's size (the signals' legend came out in one column over its own rows).
        plot->setViewport(QRect(QPoint(0, 0), size));
        plot->replot(QCustomPlot::rpImmediateRefresh);
        plot->toPainter(static_cast<QCPPainter*>(&recorder), size.width(), size.height());
    });
}

/// One bar per value (per step), or a histogram when bins are given.
void drawBars(QPainter& painter, const QRectF& target, const QVector<double>& keys, const QVector<double>& values,
              const QString& xLabel, const QString& yLabel, double width, int logicalWidth = 760)
{
    QCustomPlot plot;
    auto* bars = new QCPBars(plot.xAxis, plot.yAxis);
    bars->setData(keys, values, true);
    bars->setWidth(width);
    bars->setPen(QPen(Qt::black, 0.8));
    bars->setBrush(QColor(150, 170, 200));
    plot.xAxis->setLabel(xLabel);
    plot.yAxis->setLabel(yLabel);
    plot.rescaleAxes();
    plot.xAxis->scaleRange(1.05);
    plot.yAxis->setRangeLower(0.0);
    plot.yAxis->setRangeUpper(plot.yAxis->range().upper * 1.1);
    drawPlot(painter, &plot, target, logicalWidth);
}

/// The summary panel's bins (robust range, outliers in end bars), as bar positions and heights.
std::pair<QVector<double>, QVector<double>> histogramBars(const Histogram& h, double minimumBinWidth, double& binWidth)
{
    binWidth = h.binWidth > 0.0 ? h.binWidth : minimumBinWidth;
    QVector<double> centres, counts;
    if (h.below > 0) {
        centres << h.firstEdge - 0.5 * binWidth;
        counts << h.below;
    }
    for (std::size_t b = 0; b < h.counts.size(); ++b) {
        centres << h.binCentre(b);
        counts << h.counts[b];
    }
    if (h.above > 0) {
        centres << h.lastEdge() + 0.5 * binWidth;
        counts << h.above;
    }
    return {centres, counts};
}

QList<QStringList> summaryRows(const GaitStatistics& g, const Summary& s, std::size_t mergedMovements)
{
    QList<QStringList> rows{{tr("Figure"), tr("Value")}};
    rows << QStringList{tr("Path length (between stances)"), tr("%1 m").arg(formatFigure(g.pathLength_m, 2))}
         << QStringList{tr("Steps (strides of this foot)"),
                        mergedMovements == 0
                            ? QString::number(s.steps)
                            : tr("%1 (%2 movements without a swing, under %3 m or %4 rad/s, merged into their stances)")
                                  .arg(s.steps)
                                  .arg(mergedMovements)
                                  .arg(formatFigure(kMinStrideDistance_m, 2), formatFigure(kMinSwingRate_radps, 1))}
         << QStringList{tr("Cadence, both feet"), tr("%1 steps/min").arg(formatFigure(g.cadence_stepsPerMin, 1))}
         << QStringList{tr("Mean stride length"),
                        tr("%1 m (sd %2 m)").arg(formatFigure(g.meanStrideLength_m, 3), formatFigure(g.strideLengthStd_m, 3))}
         << QStringList{tr("Mean stride duration"), tr("%1 s").arg(formatFigure(g.meanStrideDuration_s, 3))}
         << QStringList{tr("Mean stance duration"), tr("%1 s").arg(formatFigure(g.meanStanceDuration_s, 3))}
         << QStringList{tr("End-to-start distance"),
                        tr("%1 m = %2 % of the path").arg(formatFigure(s.endToStart_m, 3), formatFigure(s.endToStartPct, 2))};
    if (g.armse)
        rows << QStringList{tr("ARMSE 2D / 3D against the reference"),
                            tr("%1 m / %2 m").arg(formatFigure(g.armse->armse2d_m, 3), formatFigure(g.armse->armse3d_m, 3))};
    if (g.loopClosure)
        rows << QStringList{tr("Loop closure (DBSE)"), tr("%1 m = %2 %").arg(formatFigure(g.loopClosure->dbse_m, 3),
                                                                           formatFigure(g.loopClosure->dbsePct, 2))};
    if (g.distanceError)
        rows << QStringList{tr("Distance error"),
                            tr("%1 m = %2 % of %3 m").arg(formatFigure(g.distanceError->error_m, 3),
                                                         formatFigure(g.distanceError->errorPct, 2),
                                                         formatFigure(g.distanceError->reference_m, 2))};
    const auto scores = [](const StanceScore& score) {
        return QStringLiteral("%1 / %2 / %3").arg(formatFigure(score.precision, 3), formatFigure(score.recall, 3),
                                                  formatFigure(score.f1, 3));
    };
    if (g.gaitStanceScore)
        rows << QStringList{tr("Gait stance (heel strike to toe off) against the labels: precision / recall / F1"),
                            scores(*g.gaitStanceScore)};
    if (g.strideCount)
        rows << QStringList{tr("Strides in the labelled trial"), tr("%1 detected, %2 labelled swings")
                                                                     .arg(g.strideCount->detected)
                                                                     .arg(g.strideCount->labelled)};
    if (g.stanceScore)
        rows << QStringList{tr("Foot at rest (ZUPT) against the labelled stance: precision / recall / F1 (the foot "
                               "rests only mid-stance: a low recall is expected)"),
                            scores(*g.stanceScore)};
    return rows;
}

/// The gait lab's figures of this foot (heel strike to toe off), means over the straight strides.
QList<QStringList> gaitRows(const GaitSummary& g)
{
    const auto mean = [&g](double value, int decimals) {
        return formatFigure(g.straightStrides > 0 ? value : std::nan(""), decimals);
    };
    QList<QStringList> rows{{tr("Figure"), tr("Value")}};
    rows << QStringList{tr("Strides (turning)"), tr("%1 (%2)").arg(g.strides).arg(g.turningStrides)}
         << QStringList{tr("Stride time"), tr("%1 s").arg(mean(g.strideTime_s, 3))}
         << QStringList{tr("Stride length"), tr("%1 m").arg(mean(g.strideLength_m, 3))}
         << QStringList{tr("Cadence"), tr("%1 steps/min").arg(mean(g.cadence_spm, 1))}
         << QStringList{tr("Stance / swing"), tr("%1 % / %2 %").arg(mean(g.stancePct, 1), mean(g.swingPct, 1))}
         << QStringList{tr("Foot clearance"), tr("%1 m").arg(mean(g.clearance_m, 3))};
    return rows;
}

QList<QStringList> bothFeetRows(const BilateralGait& walk)
{
    const DoubleSupportSummary& ds = walk.doubleSupport;
    const auto stance = [](const GaitSummary& g) { return formatFigure(g.straightStrides > 0 ? g.stancePct : std::nan(""), 1); };
    QList<QStringList> rows{{tr("Figure"), tr("Value")}};
    rows << QStringList{tr("Double support (both feet on the ground)"),
                        tr("%1 % of the gait cycle (initial %2 %, terminal %3 %), %4 strides")
                            .arg(formatFigure(ds.meanPct, 1), formatFigure(ds.initialPct, 1), formatFigure(ds.terminalPct, 1))
                            .arg(ds.cycles)}
         << QStringList{tr("Stance left / right"), tr("%1 % / %2 %").arg(stance(walk.left), stance(walk.right))}
         << QStringList{tr("Symmetry index: stride time"), tr("%1 %").arg(formatFigure(walk.symmetry.strideTimePct, 1))}
         << QStringList{tr("Symmetry index: stride length"), tr("%1 %").arg(formatFigure(walk.symmetry.strideLengthPct, 1))}
         << QStringList{tr("Symmetry index: stance"), tr("%1 %").arg(formatFigure(walk.symmetry.stancePct, 1))}
         << QStringList{tr("Symmetry index: swing"), tr("%1 %").arg(formatFigure(walk.symmetry.swingPct, 1))};
    return rows;
}

void writeGait(PageComposer& page, const ReportContent& content)
{
    const Result& result = *content.result;
    if (result.gait.strides > 0) {
        page.heading(tr("Gait (heel strike to toe off)"));
        page.paragraph(tr("From the gait events of %1: means over the strides that neither turn (more than 20 degrees) "
                          "nor pause.").arg(content.bothFeet ? tr("the left foot") : tr("this foot")));
        page.table(gaitRows(result.gait), {0.5, 0.5}, 9.0);
    }
    if (!content.bothFeet)
        return;
    page.heading(tr("Both feet"));
    page.paragraph(tr("The left and the right foot's files on one clock (their own time stamps). Symmetry index: "
                      "100 (left - right) / mean, 0 symmetric, positive where the left value is larger."));
    page.table(bothFeetRows(*content.bothFeet), {0.5, 0.5}, 9.0);
    for (const std::string& warning : content.bothFeet->warnings)
        page.paragraph(tr("Note: %1").arg(QString::fromStdString(warning)));
}

QList<QStringList> parameterRows(const Parameters& params)
{
    const Parameters defaults;
    QList<QStringList> rows{{tr("Parameter"), tr("Value"), tr("Default"), tr("Unit"), tr("Meaning")}};
    for (const ParameterField& field : parameterFields()) {
        const double value = parameterValue(params, field), standard = parameterValue(defaults, field);
        const auto text = [&field](double v) {
            switch (field.kind) {
            case ParameterField::Kind::Flag: return v != 0.0 ? tr("on") : tr("off");
            case ParameterField::Kind::Choice: {
                const auto index = static_cast<std::size_t>(v);  // as presets and --set spell it
                return index < field.choiceNames.size() ? QString::fromUtf8(field.choiceNames[index]) : QString::number(v);
            }
            case ParameterField::Kind::Real: break;
            }
            return QString::number(v, 'g', 6);
        };
        // A leading '*' makes a cell bold (and is not drawn); "* " is the mark the heading explains.
        const bool changed = value != standard;
        const QString bold = changed ? QStringLiteral("*") : QString();
        rows << QStringList{bold + (changed ? QStringLiteral("* ") : QString()) + QString::fromUtf8(field.name),
                            bold + text(value), text(standard),
                            QString::fromStdString(displayUnit(field)), QString::fromUtf8(field.description)};
    }
    return rows;
}

/// Whether the step table has the motion class and barometric height columns (there was pressure).
bool stepTableHasMotion(const Result& result)
{
    return hasBarometer(result) || hasMotionClasses(result);
}

QList<QStringList> stepRows(const Result& result)
{
    const bool motion = stepTableHasMotion(result);
    QList<QStringList> rows{{tr("Step"), tr("Stance from (s)"), tr("to (s)"), tr("Stride (m)"), tr("Stride (s)"),
                             tr("x (m)"), tr("y (m)"), tr("z (m)")}};
    if (motion)
        rows.first() << MotionLanes::tr("Motion") << MotionLanes::tr("Baro height (m)");
    for (std::size_t i = 0; i < result.steps.size(); ++i) {
        const Step& s = result.steps[i];
        // The first stance ends no stride (nothing before it): a dash, as in the window's table, not 0.000.
        const auto stride = [i](double value) { return i == 0 ? QStringLiteral("\u2013") : formatFigure(value, 3); };
        rows << QStringList{QString::number(i + 1), formatFigure(s.stanceStart_s, 2), formatFigure(s.stanceEnd_s, 2),
                            stride(s.strideLength_m), stride(s.strideDuration_s), formatFigure(s.position_m.x(), 3),
                            formatFigure(s.position_m.y(), 3), formatFigure(s.position_m.z(), 3)};
        if (motion)
            rows.last() << (s.motion == MotionClass::Unknown ? QStringLiteral("–") : motionClassLabel(s.motion))
                        << formatFigure(s.baroHeight_m, 2);
    }
    return rows;
}

QList<double> stepColumnWidths(const Result& result)
{
    if (stepTableHasMotion(result))
        return {0.07, 0.11, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.12, 0.1};
    return {0.08, 0.14, 0.12, 0.13, 0.13, 0.13, 0.13, 0.14};
}

/// Where a measurement method skipped itself or did not apply; nothing when every method ran throughout.
void writeMethodNotes(PageComposer& page, const Result& result)
{
    if (result.methodNotes.empty())
        return;
    page.heading(MotionLanes::tr("Method notes"));
    page.paragraph(MotionLanes::tr("Spans where a measurement method skipped itself or did not apply, and why; the "
                                   "other methods ran on."));
    for (const MethodNote& note : result.methodNotes)
        page.paragraph(methodNoteText(note));
}

QList<QStringList> headerRows(const ReportContent& c)
{
    const Recording& recording = *c.recording;
    return {{tr("Recording"), QFileInfo(c.recordingPath).fileName()},
            {tr("Format"), QString::fromStdString(c.info.format)},
            {tr("Sensor / device"), c.device.isEmpty() ? tr("not stated in the file") : c.device},
            {tr("Duration"), tr("%1 s, %2 samples").arg(formatFigure(recording.duration_s(), 1)).arg(recording.samples.size())},
            {tr("Sample rate"), tr("%1 Hz").arg(formatFigure(c.info.rate_hz, 1))},
            {tr("Parameters"), c.parameterSource},
            {tr("Method set"), methodSetName(c.parameters)},
            {tr("Report made"), QDateTime::currentDateTime().toString(Qt::ISODate)},
            {tr("Software"), tr("Footpath %1").arg(QCoreApplication::applicationVersion())}};
}

/// A window of about ten seconds, enough strides to read the lanes: from just before the first
/// missed stance when there is one (where the detector view explains the failure), else in the
/// middle of the walk.
std::pair<double, double> representativeWindow(const Result& result)
{
    const double from = result.time_s.front(), to = result.time_s.back();
    const double half = std::min(5.0, 0.5 * (to - from));
    const auto missed = std::find_if(result.warnings.begin(), result.warnings.end(), [](const PlausibilityWarning& w) {
        return w.kind == PlausibilityWarning::Kind::LongSwing;
    });
    const double middle = missed != result.warnings.end() ? missed->start_s - 1.0 + half : 0.5 * (from + to);
    const double centre = std::clamp(middle, from + half, to - half);
    return {centre - half, centre + half};
}

QString detectorFigureCaption(const Parameters& params, double from, double to)
{
    if (params.detectorKind() == DetectorKind::PaperC1C2C3)
        return tr("Figure 5. Stance detector C1/C2/C3 from %1 s to %2 s: conditions C1, C2, C3, their combination C, "
                  "the median-filtered stance, the std of |a| on a logarithmic axis, and the inputs with their "
                  "thresholds; plausibility warnings shaded red.")
            .arg(formatFigure(from, 1), formatFigure(to, 1));
    const ParameterField* detector = findParameterField("detector");
    return tr("Figure 5. Stance detector %3 from %1 s to %2 s: the condition C (statistic below threshold), the "
              "stance, and the statistic on a logarithmic axis with its threshold; plausibility warnings shaded red.")
        .arg(formatFigure(from, 1), formatFigure(to, 1),
             QString::fromUtf8(detector->choiceLabels.at(static_cast<std::size_t>(params.detector))));
}

/// Every finding of the plausibility checks with its time span, or a line saying there are none.
void writeWarnings(PageComposer& page, const Result& result)
{
    page.heading(tr("Plausibility warnings"));
    if (result.warnings.empty()) {
        page.paragraph(tr("The plausibility checks found nothing: the result looks like human gait."));
        return;
    }
    page.paragraph(tr("Findings: %1. Each marks a span where the result is not what human gait gives, so the path "
                      "needs care there.").arg(result.warnings.size()));
    for (const PlausibilityWarning& w : result.warnings)
        page.paragraph(tr("%1, %2: %3").arg(warningSpanText(w), warningLabel(w.kind), QString::fromStdString(w.message)));
}

/// The comparison table as the window shows it, the best value per column in bold with a star.
void writeComparison(PageComposer& page, const std::vector<ComparisonRow>& rows, bool stale)
{
    if (rows.empty())
        return;
    page.heading(stale ? tr("Method comparison (stale)") : tr("Method comparison"));
    if (stale)
        page.paragraph(tr("Stale: the parameters changed after this comparison ran, so its rows were estimated with "
                          "other parameters than the rest of this report. Run the comparison again to update it."),
                       9.0, true);
    page.paragraph(tr("Every method set run on this recording with the same detector and noise parameters; the best "
                      "value of a column is in bold and marked %1.").arg(bestMarker().trimmed()));
    const std::vector<ComparisonColumn> columns = comparisonColumns(rows);
    QList<QStringList> cells{QStringList()};
    QList<double> widths;
    for (const ComparisonColumn& column : columns) {
        cells.first() << QString(column.title).replace(QLatin1Char('\n'), QLatin1Char(' '));
        // The set's name and the warnings (or the error) get the room; the figures share the rest.
        widths << (&column == &columns.front() ? 0.22 : &column == &columns.back() ? 0.18 : 0.6 / static_cast<double>(columns.size() - 2));
    }
    for (const ComparisonRow& row : rows) {
        QStringList line;
        for (const ComparisonColumn& column : columns)
            line << column.text(row);
        cells << line;
    }
    for (std::size_t c = 0; c < columns.size(); ++c)
        if (const int best = bestRowOfColumn(rows, columns[c]); best >= 0)
            cells[best + 1][static_cast<int>(c)] = QLatin1Char('*') + cells[best + 1][static_cast<int>(c)] + bestMarker();
    page.table(cells, widths, 7.5);
}

void drawHeightOverTime(QPainter& painter, const Result& result, const QRectF& target)
{
    QCustomPlot plot;
    QVector<double> t, z;
    for (std::size_t k = 0; k < result.time_s.size(); ++k) {
        t << result.time_s[k];
        z << result.position_m[k].z();
    }
    plot.addGraph()->setData(t, z, true);
    plot.graph(0)->setPen(QPen(Qt::black, 1.2));
    plot.xAxis->setLabel(tr("time (s)"));
    plot.yAxis->setLabel(tr("height z (m)"));
    plot.rescaleAxes();
    plot.yAxis->scaleRange(1.1);
    drawPlot(painter, &plot, target);
}

void drawGaitFigures(PageComposer& page, QPainter& painter, const ResultEvaluation& evaluation)
{
    const GaitStatistics& g = evaluation.statistics;
    QVector<double> strideSteps, strides, stanceSteps, stances;
    for (std::size_t i = 0; i < g.strideLengths_m.size(); ++i) {
        strideSteps << double(i + 2);  // the stride that ends at stance phase i + 2 (the first has none)
        strides << g.strideLengths_m[i];
    }
    for (std::size_t i = 0; i < g.stanceDurations_s.size(); ++i) {
        stanceSteps << double(i + 1);
        stances << g.stanceDurations_s[i];
    }
    page.figure(tr("Figure 6. Stride length per step."), page.mm(50), [&](const QRectF& r) {
        drawBars(painter, r, strideSteps, strides, tr("step"), tr("stride length (m)"), 0.7);
    });
    page.figure(tr("Figure 7. Stance duration per step."), page.mm(50), [&](const QRectF& r) {
        drawBars(painter, r, stanceSteps, stances, tr("step"), tr("stance duration (s)"), 0.7);
    });
    double strideWidth = 0.0, stanceWidth = 0.0;
    // Pairs, not structured bindings: C++17 does not let the lambda below capture those (clang refuses).
    const auto strideHistogram = histogramBars(evaluation.strideLengths, kStrideLengthBin_m, strideWidth);
    const auto stanceHistogram = histogramBars(evaluation.stanceDurations, kStanceDurationBin_s, stanceWidth);
    page.figure(tr("Figure 8. Histograms of stride length (left) and stance duration (right)."), page.mm(50),
                [&](const QRectF& r) {
                    const QRectF left(r.left(), r.top(), r.width() / 2 - page.mm(2), r.height());
                    const QRectF right(r.center().x() + page.mm(2), r.top(), r.width() / 2 - page.mm(2), r.height());
                    painter.save();
                    drawBars(painter, left, strideHistogram.first, strideHistogram.second, tr("stride length (m)"),
                             tr("strides"), strideWidth * 0.9, 380);
                    painter.restore();
                    drawBars(painter, right, stanceHistogram.first, stanceHistogram.second, tr("stance duration (s)"),
                             tr("stances"), stanceWidth * 0.9, 380);
                });
}

/// The gait lab's stance (heel strike to toe off) and the foot clearance of every gait stride.
void drawGaitStrideFigures(PageComposer& page, QPainter& painter, const std::vector<GaitStride>& gaitStrides)
{
    if (gaitStrides.empty())
        return;
    QVector<double> numbers, stancePct, clearance;
    for (const GaitStride& stride : gaitStrides) {
        numbers << double(numbers.size() + 1);
        stancePct << stride.stancePct;
        clearance << stride.clearance_m;
    }
    page.figure(tr("Figure 9. Gait stance (heel strike to toe off, left) and foot clearance (right) per stride."),
                page.mm(50), [&](const QRectF& r) {
                    const QRectF left(r.left(), r.top(), r.width() / 2 - page.mm(2), r.height());
                    const QRectF right(r.center().x() + page.mm(2), r.top(), r.width() / 2 - page.mm(2), r.height());
                    painter.save();
                    drawBars(painter, left, numbers, stancePct, tr("stride"), tr("stance (% of the stride)"), 0.7, 380);
                    painter.restore();
                    drawBars(painter, right, numbers, clearance, tr("stride"), tr("clearance (m)"), 0.7, 380);
                });
}

void drawFigures(PageComposer& page, QPainter& painter, const ReportContent& c, const ResultEvaluation& evaluation)
{
    const Result& result = *c.result;
    TrajectoryView2D view2D;
    view2D.resize(900, 640);
    view2D.setResult(c.result);
    view2D.setPathLabel(c.pathLabel);
    view2D.setOverlays(c.otherPaths);
    view2D.setReference(evaluation.alignedReference);
    // A long walk's stances are too close at the page's scale to be marked (as on screen).
    const QString caption =
        view2D.layOutForPrinting() || result.steps.empty()
            ? tr("Figure 1. The foot path seen from above (stance positions as dots; reference dashed when present).")
            : tr("Figure 1. The foot path seen from above (reference dashed when present; the stances are too "
                 "close together at this scale to be marked).");
    page.figure(caption, page.mm(110), [&](const QRectF& r) { drawPlot(painter, view2D.plot(), r); });
    page.figure(tr("Figure 2. Height of the foot over time."), page.mm(50),
                [&](const QRectF& r) { drawHeightOverTime(painter, result, r); });
    TrajectoryView3D view3D;
    view3D.resize(900, 600);
    view3D.setResult(c.result);
    view3D.setPathLabel(c.pathLabel);
    view3D.setOverlays(c.otherPaths);
    view3D.setReference(evaluation.alignedReference);
    // drawScaled renders the figure 760 units wide at the figure's proportions, whatever its scale.
    constexpr int kFigure3Width = 760;
    const double figure3Height = page.mm(100);
    const QRectF figure3Drawn(0.0, 0.0, kFigure3Width, kFigure3Width * figure3Height / page.width());
    const QString caption3 =
        view3D.marksStances(figure3Drawn) || result.steps.empty()
            ? tr("Figure 3. The path in 3D (stance positions as dots; reference dashed when present).")
            : tr("Figure 3. The path in 3D (reference dashed when present; the stances are too close together "
                 "at this scale to be marked).");
    page.figure(caption3, figure3Height, [&](const QRectF& r) {
        drawScaled(painter, r, kFigure3Width, [&view3D](QPainter& recorder, QSize size) {
            view3D.render(recorder, QRectF(QPointF(0, 0), QSizeF(size)));
        });
    });
    SignalPlots signalPlots;
    signalPlots.resize(900, 700);
    signalPlots.setRecording(c.recording);
    signalPlots.setResult(c.result);
    page.figure(tr("Figure 4. Signals, stance shaded."), page.mm(120),
                [&](const QRectF& r) { drawPlot(painter, signalPlots.plot(), r); });
    // C1/C2/C3 has five lanes and three input rows to show; a statistic detector two lanes.
    const bool paper = c.parameters.detectorKind() == DetectorKind::PaperC1C2C3;
    StanceFlagsPlot flags;
    flags.resize(900, paper ? 880 : 570);
    flags.setRecording(c.recording);
    flags.setParameters(c.parameters);
    flags.setResult(c.result);
    flags.setInputsVisible(true);
    const auto [from, to] = representativeWindow(result);
    flags.setTimeRange(from, to);
    page.figure(detectorFigureCaption(c.parameters, from, to), page.mm(paper ? 170 : 110),
                [&](const QRectF& r) { drawPlot(painter, flags.plot(), r); });
    drawGaitFigures(page, painter, evaluation);
    drawGaitStrideFigures(page, painter, result.gaitStrides);
}

}  // namespace

QString methodSetName(const Parameters& params)
{
    const std::string spec = methodSetSpec(params);
    return spec.empty() ? tr("none") : methodSetText(spec);
}

QString writePdfReport(const ReportContent& content, const QString& path, QPageSize::PageSizeId pageSize)
{
    if (!content.recording || !content.result || content.result->time_s.empty())
        return tr("nothing to report: no estimate yet");
    QPdfWriter writer(path);
    writer.setPageSize(QPageSize(pageSize));
    writer.setPageMargins(QMarginsF(18, 16, 18, 16), QPageLayout::Millimeter);
    writer.setResolution(300);
    writer.setTitle(tr("Footpath report: %1").arg(QFileInfo(content.recordingPath).fileName()));
    writer.setCreator(QStringLiteral("Footpath"));
    QCPPainter painter;
    if (!painter.begin(&writer))
        return tr("%1: cannot write the PDF").arg(path);
    painter.setMode(QCPPainter::pmVectorized);
    painter.setMode(QCPPainter::pmNoCaching);
    PageComposer page(writer, painter);
    page.paragraph(tr("Footpath report"), 18.0, true);
    page.paragraph(QFileInfo(content.recordingPath).fileName(), 11.0);
    page.table(headerRows(content), {0.3, 0.7}, 9.0, false);
    page.heading(tr("Summary"));
    const Result& result = *content.result;
    // The window's evaluation of this result when it hands one over; made once here otherwise.
    const std::shared_ptr<const ResultEvaluation> evaluation =
        content.evaluation ? content.evaluation
                           : std::make_shared<const ResultEvaluation>(evaluate(result, content.recording.get()));
    page.table(summaryRows(evaluation->statistics, result.summary, result.mergedMovements.size()), {0.5, 0.5}, 9.0);
    if (const QString motion = motionCountsSentence(*content.result); !motion.isEmpty())
        page.paragraph(MotionLanes::tr("Motion (barometer): %1.").arg(motion));
    writeGait(page, content);
    writeWarnings(page, *content.result);
    writeMethodNotes(page, *content.result);
    writeComparison(page, content.comparison, content.comparisonStale);
    // The heading with its first figure (at its smallest), not alone at the foot of a page.
    page.ensureRoom(page.mm(12 + 0.65 * 110 + 8));
    page.heading(tr("Figures"));
    drawFigures(page, painter, content, *evaluation);
    // The values' columns as wide as a number of six digits in bold ("0.000958747" wrapped after
    // its point at 0.12 of the page).
    const QList<QStringList> parameters = parameterRows(content.parameters);
    const QList<double> parameterWidths{0.22, 0.15, 0.13, 0.08, 0.42};
    page.keepHeadingWithTable(parameters, parameterWidths, 7.5);
    page.heading(tr("Parameters (* and bold: differs from the default)"));
    page.table(parameters, parameterWidths, 7.5);
    const QList<QStringList> steps = stepRows(*content.result);
    page.keepHeadingWithTable(steps, stepColumnWidths(*content.result), 7.5);
    page.heading(tr("Steps"));
    page.table(steps, stepColumnWidths(*content.result), 7.5);
    // What reading the file raised, apart from the plausibility of the result (its own section).
    page.heading(tr("Import notes (reading the file)"));
    for (const std::string& note : content.recording->reference.notes)
        page.paragraph(QString::fromStdString(note));
    for (const std::string& warning : content.recording->warnings)
        page.paragraph(tr("Import warning: %1").arg(QString::fromStdString(warning)));
    if (content.recording->warnings.empty())
        page.paragraph(tr("Reading the file raised no warnings."));
    painter.end();
    return {};
}

}  // namespace footpath
