#include "MotionLanes.h"

#include "TimeBands.h"
#include "methods/MethodRegistry.h"
#include "nav/Parameters.h"

#include <QCoreApplication>
#include <QLocale>
#include <QToolTip>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace footpath {

namespace {

constexpr double kFloorHeight_m = 3.0;  ///< what "a floor" means in the counts sentence
constexpr std::size_t kMaxNoteLevels = 4;
const QColor kGreyedFill(236, 236, 236);
const QColor kGreyedText(130, 130, 130);
const QColor kNoteColour(196, 178, 232);  // lavender: parts from the red warnings and the class colours

QString decimals(double value, int places) { return QLocale().toString(value, 'f', places); }

/// Dark text on light fills, white on dark ones.
QColor textColourOn(const QColor& fill) { return fill.lightnessF() > 0.55 ? QColor(20, 20, 20) : QColor(Qt::white); }

double strideStart(const Result& result, std::size_t step)
{
    if (step > 0)
        return result.steps[step - 1].stanceEnd_s;
    return result.time_s.empty() ? result.steps.front().stanceStart_s : result.time_s.front();
}

QString motionSpanToolTip(const Result& result, const MotionSpan& span)
{
    const Step& first = result.steps[span.firstStep];
    const Step& last = result.steps[span.lastStep];
    QString text = MotionLanes::tr("<b>%1</b>: steps %2\u2013%3 (%4\u2013%5 s)")
                       .arg(motionClassLabel(span.motion))
                       .arg(span.firstStep + 1)
                       .arg(span.lastStep + 1)
                       .arg(decimals(span.start_s, 1), decimals(span.end_s, 1));
    const double from = span.firstStep > 0 ? result.steps[span.firstStep - 1].baroHeight_m : first.baroHeight_m;
    if (std::isfinite(from) && std::isfinite(last.baroHeight_m))
        text += MotionLanes::tr("<br>barometric height %1 \u2192 %2 m").arg(decimals(from, 1), decimals(last.baroHeight_m, 1));
    return text;
}

}  // namespace

QString motionClassLabel(MotionClass motion)
{
    switch (motion) {
    case MotionClass::Level: return MotionLanes::tr("Level");
    case MotionClass::StairsUp: return MotionLanes::tr("Stairs up");
    case MotionClass::StairsDown: return MotionLanes::tr("Stairs down");
    case MotionClass::ElevatorUp: return MotionLanes::tr("Elevator up");
    case MotionClass::ElevatorDown: return MotionLanes::tr("Elevator down");
    case MotionClass::Unknown: break;
    }
    return MotionLanes::tr("Unclassified");
}

QColor motionClassColour(MotionClass motion)
{
    switch (motion) {
    case MotionClass::Level: return QColor(140, 185, 125);  // dark enough for a thin path on white
    case MotionClass::StairsUp: return QColor(214, 60, 130);  // not the stance markers' amber
    case MotionClass::StairsDown: return QColor(66, 146, 210);
    case MotionClass::ElevatorUp: return QColor(120, 20, 60);
    case MotionClass::ElevatorDown: return QColor(30, 50, 140);
    case MotionClass::Unknown: break;
    }
    return QColor(175, 175, 175);
}

bool hasMotionClasses(const Result& result)
{
    return std::any_of(result.steps.begin(), result.steps.end(),
                       [](const Step& step) { return step.motion != MotionClass::Unknown; });
}

bool hasBarometer(const Result& result)
{
    return std::any_of(result.steps.begin(), result.steps.end(),
                       [](const Step& step) { return std::isfinite(step.baroHeight_m); });
}

std::vector<MotionSpan> motionSpans(const Result& result)
{
    std::vector<MotionSpan> spans;
    for (std::size_t k = 0; k < result.steps.size(); ++k) {
        const Step& step = result.steps[k];
        if (step.motion == MotionClass::Unknown)
            continue;
        if (!spans.empty() && spans.back().motion == step.motion && spans.back().lastStep + 1 == k) {
            spans.back().end_s = step.stanceEnd_s;
            spans.back().lastStep = k;
            continue;
        }
        spans.push_back(MotionSpan{step.motion, strideStart(result, k), step.stanceEnd_s, k, k});
    }
    return spans;
}

std::vector<MotionClass> motionOfSamples(const Result& result)
{
    std::vector<MotionClass> classes(result.time_s.size(), MotionClass::Unknown);
    std::size_t step = 0;
    for (std::size_t k = 0; k < result.time_s.size(); ++k) {
        while (step < result.steps.size() && result.steps[step].stanceEnd_s < result.time_s[k])
            ++step;
        if (step == result.steps.size())
            break;
        classes[k] = result.steps[step].motion;
    }
    return classes;
}

std::vector<MotionClass> motionClassesIn(const std::vector<MotionClass>& classes)
{
    std::vector<MotionClass> present;
    for (const MotionClass motion : {MotionClass::Unknown, MotionClass::Level, MotionClass::StairsUp,
                                     MotionClass::StairsDown, MotionClass::ElevatorUp, MotionClass::ElevatorDown})
        if (std::find(classes.begin(), classes.end(), motion) != classes.end())
            present.push_back(motion);
    return present;
}

QString motionCountsSentence(const Result& result)
{
    if (!hasMotionClasses(result))
        return {};
    const Summary& s = result.summary;
    QStringList parts;
    const auto stairs = [&parts](std::size_t steps, double height_m, bool up) {
        if (steps == 0 && height_m <= 0.0)
            return;
        const auto floors = static_cast<int>(std::lround(height_m / kFloorHeight_m));
        // Singular and plural spelled out: without an English translation file, "%n floor(s)" would
        // show as it is written.
        if (floors == 1)
            parts << (up ? MotionLanes::tr("1 floor up by stairs (%1 m)") : MotionLanes::tr("1 floor down by stairs (%1 m)"))
                             .arg(decimals(height_m, 1));
        else if (floors > 1)
            parts << (up ? MotionLanes::tr("%1 floors up by stairs (%2 m)") : MotionLanes::tr("%1 floors down by stairs (%2 m)"))
                             .arg(floors)
                             .arg(decimals(height_m, 1));
        else
            parts << (up ? MotionLanes::tr("%1 m up by stairs") : MotionLanes::tr("%1 m down by stairs"))
                             .arg(decimals(height_m, 1));
    };
    stairs(s.stairStepsUp, s.stairsClimb_m, true);
    stairs(s.stairStepsDown, s.stairsDescent_m, false);
    if (s.elevatorRides > 0)
        parts << (s.elevatorRides == 1 ? MotionLanes::tr("1 elevator ride")
                                       : MotionLanes::tr("%1 elevator rides").arg(s.elevatorRides));
    if (parts.isEmpty())
        return MotionLanes::tr("Level walking only: no stairs or elevator");
    return parts.join(QStringLiteral(", "));
}

QString methodLabel(const std::string& method)
{
    // The method's own label in the parameter list: the lanes, the notes and the panel name a method
    // alike (the lane said "Heading drift reduction" where the panel said "Heuristic ...").
    if (const SourceMethod* source = findSourceMethod(method))
        if (const ParameterField* field = findParameterField(source->switchName))
            return QCoreApplication::translate("footpath::ParameterFields", field->label);
    for (const EstimatorMethod& estimator : estimatorMethods())
        if (method == estimator.token && *estimator.laneLabel)
            return QCoreApplication::translate("footpath::MotionLanes", estimator.laneLabel);
    return QString::fromStdString(method);
}

QString methodNoteSpanText(const MethodNote& note)
{
    return MotionLanes::tr("%1\u2013%2 s").arg(decimals(note.start_s, 1), decimals(note.end_s, 1));
}

QString methodNoteText(const MethodNote& note)
{
    return MotionLanes::tr("%1, %2: %3")
        .arg(methodLabel(note.method), methodNoteSpanText(note), QString::fromStdString(note.message));
}

/// A lane's bars: each on the first level free at its left end (one level when none overlap),
/// labelled when the label fits in the bar; or, while greyed, the lane grey with the placeholder.
class MotionLanes::Bars : public QCPLayerable {
public:
    Bars(const MotionLanes* owner, QCPAxisRect* lane, const std::vector<LaneBar>* bars, bool greyable)
        : QCPLayerable(lane->parentPlot(), QString(), lane), owner_(owner), lane_(lane), bars_(bars), greyable_(greyable)
    {
    }

    static double levelHeight(const QCustomPlot* plot) { return QFontMetricsF(laneLabelFont(plot)).height() + 4.0; }

protected:
    void applyDefaultAntialiasingHint(QCPPainter* painter) const override { painter->setAntialiasing(false); }
    QRect clipRect() const override { return lane_->rect(); }

    void draw(QCPPainter* painter) override
    {
        painter->setFont(laneLabelFont(parentPlot()));
        if (greyable_ && owner_->isMotionGreyed()) {
            painter->fillRect(lane_->rect(), kGreyedFill);
            painter->setPen(kGreyedText);
            painter->drawText(QRectF(lane_->rect()).adjusted(6, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter,
                              owner_->placeholder());
            return;
        }
        const double height = levelHeight(parentPlot());
        const auto levels = static_cast<std::size_t>(std::max(1.0, std::floor((lane_->height() - 1.0) / height)));
        std::vector<double> levelEnds(levels, -std::numeric_limits<double>::infinity());
        for (const LaneBar& bar : *bars_)
            if (const std::optional<QRectF> rect = place(bar, levelEnds, height))
                drawBar(painter, bar, *rect);
    }

private:
    /// The bar's rectangle in pixels on the first level free at its left end (else the one that
    /// frees first); nothing when it is out of view.
    std::optional<QRectF> place(const LaneBar& bar, std::vector<double>& levelEnds, double height) const
    {
        const QCPAxis* time = lane_->axis(QCPAxis::atBottom);
        if (bar.end_s < time->range().lower || bar.start_s > time->range().upper)
            return std::nullopt;
        const QRect area = lane_->rect();
        const double left = std::max(time->coordToPixel(bar.start_s), static_cast<double>(area.left()));
        const double right = std::max(left + 2.0, std::min(time->coordToPixel(bar.end_s), area.right() + 1.0));
        auto level = std::find_if(levelEnds.begin(), levelEnds.end(), [left](double end) { return end <= left; });
        if (level == levelEnds.end())
            level = std::min_element(levelEnds.begin(), levelEnds.end());
        *level = right;
        const double top = area.top() + 1.0 + static_cast<double>(level - levelEnds.begin()) * height;
        return QRectF(left, top, right - left, height - 1.0);
    }

    static void drawBar(QCPPainter* painter, const LaneBar& bar, const QRectF& rect)
    {
        painter->fillRect(rect, bar.colour);
        const double textWidth = QFontMetricsF(painter->font(), painter->device()).horizontalAdvance(bar.label);
        if (textWidth + 6.0 > rect.width())
            return;  // no room: the tool tip names it
        painter->setPen(textColourOn(bar.colour));
        painter->drawText(rect.adjusted(3.0, 0.0, 0.0, 0.0), Qt::AlignLeft | Qt::AlignVCenter, bar.label);
    }

    const MotionLanes* owner_;
    QCPAxisRect* lane_;
    const std::vector<LaneBar>* bars_;
    bool greyable_;
};

MotionLanes::MotionLanes(QCustomPlot* plot) : QObject(plot), plot_(plot)
{
    connect(plot_, &QCustomPlot::mouseMove, this, &MotionLanes::onMouseMove);
    connect(plot_, &QCustomPlot::beforeReplot, this, &MotionLanes::fitLaneHeights);  // the font may have changed
}

void MotionLanes::setUpLane(QCPAxisRect* lane, const QString& name, std::vector<LaneBar>* bars, bool greyable)
{
    footpath::setUpLane(lane, name);
    (new Bars(this, lane, bars, greyable))->setLayer(QStringLiteral("main"));
}

void MotionLanes::setMotionLane(QCPAxisRect* lane)
{
    motionLane_ = lane;
    setUpLane(lane, tr("Motion"), &motionBars_, true);
    fitLaneHeights();
}

void MotionLanes::setNotesLane(QCPAxisRect* lane)
{
    notesLane_ = lane;
    setUpLane(lane, tr("Method notes"), &noteBars_, false);
    fitLaneHeights();
}

void MotionLanes::setResult(const Result* result)
{
    hasResult_ = result != nullptr;
    barometer_ = false;
    motionBars_.clear();
    noteBars_.clear();
    placeholder_.clear();
    if (!result) {
        fitLaneHeights();
        return;
    }
    for (const MotionSpan& span : motionSpans(*result))
        motionBars_.push_back(LaneBar{span.start_s, span.end_s, motionClassColour(span.motion),
                                      motionClassLabel(span.motion), motionSpanToolTip(*result, span)});
    barometer_ = hasBarometer(*result);
    placeholder_ = tr("barometer present, steps not classified (use_baro off?)");
    for (const MethodNote& note : result->methodNotes)
        noteBars_.push_back(LaneBar{note.start_s, note.end_s, kNoteColour, methodLabel(note.method),
                                    QStringLiteral("<p>%1</p>").arg(methodNoteText(note).toHtmlEscaped())});
    fitLaneHeights();
}

void MotionLanes::fitLaneHeights()
{
    const double levelHeight = Bars::levelHeight(plot_);
    const auto fix = [](QCPAxisRect* lane, double height) {
        if (lane == nullptr)
            return;
        lane->setMinimumSize(0, static_cast<int>(std::ceil(height)));
        lane->setMaximumSize(QWIDGETSIZE_MAX, static_cast<int>(std::ceil(height)));
    };
    fix(motionLane_, levelHeight + 2.0);
    const std::size_t levels = std::clamp<std::size_t>(overlapDepth(noteBars_), 1, kMaxNoteLevels);
    fix(notesLane_, static_cast<double>(levels) * levelHeight + 2.0);
}

QString MotionLanes::toolTipAt(const QCPAxisRect* lane, double time_s) const
{
    const std::vector<LaneBar>* bars = lane == motionLane_ ? &motionBars_ : (lane == notesLane_ ? &noteBars_ : nullptr);
    if (bars == nullptr)
        return {};
    QStringList tips;
    for (const LaneBar& bar : *bars)
        if (bar.start_s <= time_s && time_s <= bar.end_s)
            tips << bar.toolTip;
    if (tips.isEmpty() && lane == motionLane_ && isMotionGreyed())
        return placeholder_;
    return tips.join(QStringLiteral("<br>"));
}

void MotionLanes::onMouseMove(QMouseEvent* event)
{
    const QPoint pos = event->position().toPoint();
    QString text;
    for (const QCPAxisRect* lane : {motionLane_, notesLane_})
        if (lane != nullptr && lane->layout() != nullptr && lane->rect().contains(pos))
            text = toolTipAt(lane, lane->axis(QCPAxis::atBottom)->pixelToCoord(pos.x()));
    if (!text.isEmpty()) {
        QToolTip::showText(event->globalPosition().toPoint(), text, plot_);
        shownToolTip_ = text;
    } else if (!shownToolTip_.isEmpty()) {
        // Only ours: the warning overlay may have just shown its own for the row under the pointer.
        if (QToolTip::text() == shownToolTip_)
            QToolTip::hideText();
        shownToolTip_.clear();
    }
}

}  // namespace footpath
