#include "WarningOverlay.h"

#include "TimeBands.h"

#include <QToolTip>
#include <qcustomplot.h>

#include <algorithm>
#include <limits>
#include <optional>

namespace footpath {

namespace {

using Kind = PlausibilityWarning::Kind;

const QString kBandLayer = QStringLiteral("warnings");
// Red, so it parts from the amber stance shading; light, so the curves stay readable through it.
const QColor kBandColour(235, 60, 40, 38);
const QColor kBarColour(240, 140, 120);
const QColor kWholeWalkBarColour(248, 205, 190);
const QColor kLabelColour(90, 10, 0);
constexpr std::size_t kMaxLaneLevels = 6;

QString number(double value) { return QString::number(value, 'f', 2); }

/// The union of the local findings' spans, sorted and disjoint, as TimeBands needs them.
std::vector<QCPRange> localSpans(const std::vector<PlausibilityWarning>& warnings)
{
    std::vector<QCPRange> spans;
    for (const PlausibilityWarning& w : warnings)
        if (!concernsWholeWalk(w.kind))
            spans.emplace_back(w.start_s, w.end_s);
    std::sort(spans.begin(), spans.end(), [](const QCPRange& a, const QCPRange& b) { return a.lower < b.lower; });
    std::vector<QCPRange> merged;
    for (const QCPRange& span : spans) {
        if (!merged.empty() && span.lower <= merged.back().upper)
            merged.back().upper = std::max(merged.back().upper, span.upper);
        else
            merged.push_back(span);
    }
    return merged;
}

}  // namespace

QString warningLabel(Kind kind)
{
    switch (kind) {
    case Kind::NoInitialRest: return WarningOverlay::tr("no initial rest");
    case Kind::LongSwing: return WarningOverlay::tr("missed stance");
    case Kind::StrideLength: return WarningOverlay::tr("stride too long");
    case Kind::StrideDuration: return WarningOverlay::tr("stride too slow");
    case Kind::StanceRatio: return WarningOverlay::tr("stance share");
    case Kind::ImplausibleSpeed: return WarningOverlay::tr("foot too fast");
    case Kind::FewStances: return WarningOverlay::tr("few stances");
    case Kind::BarometerGap: return WarningOverlay::tr("height vs barometer");
    }
    return QString::fromUtf8(warningKindName(kind));
}

QString warningSpanText(const PlausibilityWarning& warning)
{
    return WarningOverlay::tr("%1\u2013%2 s").arg(number(warning.start_s), number(warning.end_s));
}

bool concernsWholeWalk(Kind kind)
{
    return kind == Kind::StanceRatio || kind == Kind::FewStances || kind == Kind::BarometerGap;
}

std::vector<std::size_t> warningsOfStep(const Result& result, std::size_t step)
{
    std::vector<std::size_t> found;
    if (step >= result.steps.size())
        return found;
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    const double from = step == 0 ? -kInfinity : result.steps[step - 1].stanceEnd_s;
    const double to = step + 1 == result.steps.size() ? kInfinity : result.steps[step].stanceEnd_s;
    for (std::size_t i = 0; i < result.warnings.size(); ++i) {
        const PlausibilityWarning& w = result.warnings[i];
        // Half-open [from, to), so a finding that ends where a stride ends is not also the next one's.
        if (!concernsWholeWalk(w.kind) && w.start_s < to && (w.end_s > from || (w.end_s == w.start_s && w.start_s >= from)))
            found.push_back(i);
    }
    return found;
}

QString warningsToolTip(const std::vector<PlausibilityWarning>& warnings, const std::vector<std::size_t>& which)
{
    QStringList lines;
    for (const std::size_t i : which) {
        const PlausibilityWarning& w = warnings[i];
        lines << QStringLiteral("<b>%1</b> (%2): %3")
                     .arg(warningLabel(w.kind).toHtmlEscaped(), warningSpanText(w),
                          QString::fromStdString(w.message).toHtmlEscaped());
    }
    return lines.isEmpty() ? QString() : QStringLiteral("<p>") + lines.join(QStringLiteral("</p><p>")) + QStringLiteral("</p>");
}

LabelPlace warningLabelPlace(double textWidth, double minInside, double left, double right, double laneLeft,
                             double laneRight)
{
    constexpr double kPadding = 3.0;
    const double inside = right - left - 2.0 * kPadding;
    if (textWidth <= inside || inside >= minInside)
        return {left + kPadding, std::min(textWidth, inside), true};
    if (right + kPadding + textWidth <= laneRight)
        return {right + kPadding, textWidth, false};
    const double start = std::max(laneLeft, left - kPadding - textWidth);
    return {start, std::max(0.0, std::min(textWidth, left - kPadding - start)), false};
}

/// The lane: one bar per finding over its span with its short label, on the first level where
/// neither bar nor label runs into an earlier one. Findings about the whole walk get a paler bar.
class WarningOverlay::LaneBars : public QCPLayerable {
public:
    LaneBars(const WarningOverlay* overlay, QCPAxisRect* lane)
        : QCPLayerable(lane->parentPlot(), QString(), lane), overlay_(overlay), lane_(lane)
    {
    }

    static double levelHeight(const QCustomPlot* plot) { return QFontMetricsF(laneLabelFont(plot)).height() + 3.0; }

protected:
    void applyDefaultAntialiasingHint(QCPPainter* painter) const override { painter->setAntialiasing(false); }
    QRect clipRect() const override { return lane_->rect(); }

    void draw(QCPPainter* painter) override
    {
        painter->setFont(laneLabelFont(parentPlot()));
        const double height = levelHeight(parentPlot());
        const auto levels = static_cast<std::size_t>(std::max(1.0, std::floor((lane_->height() - 2.0) / height)));
        std::vector<double> levelEnds(levels, -std::numeric_limits<double>::infinity());  // in pixels
        for (const PlausibilityWarning* w : labellingOrder())
            if (const std::optional<std::pair<double, double>> span = pixelSpan(*w))
                drawBar(painter, *w, *span, levelEnds);
    }

private:
    /// Local findings take the levels first: a whole-walk finding is the one to go unlabelled.
    std::vector<const PlausibilityWarning*> labellingOrder() const
    {
        std::vector<const PlausibilityWarning*> order;
        for (const bool wholeWalk : {false, true})
            for (const PlausibilityWarning& w : overlay_->warnings_)
                if (concernsWholeWalk(w.kind) == wholeWalk)
                    order.push_back(&w);
        return order;
    }

    /// The bar on the first level free at its left end, labelled; without a free level, outlined on
    /// the level it overlaps least and unlabelled (the tool tip still names it).
    void drawBar(QCPPainter* painter, const PlausibilityWarning& w, std::pair<double, double> span,
                 std::vector<double>& levelEnds) const
    {
        const auto [left, right] = span;
        const QFontMetricsF metrics(painter->font(), painter->device());
        const QRectF label = labelPlace(metrics, warningLabel(w.kind), left, right);
        const double occupiedFrom = std::min(left, label.left()), occupiedTo = std::max(right, label.right());
        auto level = std::find_if(levelEnds.begin(), levelEnds.end(),
                                  [from = occupiedFrom](double end) { return end + 3.0 < from; });
        const bool labelled = level != levelEnds.end();
        if (!labelled)
            level = std::min_element(levelEnds.begin(), levelEnds.end());
        const double height = levelHeight(parentPlot());
        const QRectF bar(left, lane_->top() + 2.0 + static_cast<double>(level - levelEnds.begin()) * height,
                         right - left, height - 2.0);
        if (labelled) {
            painter->fillRect(bar, concernsWholeWalk(w.kind) ? kWholeWalkBarColour : kBarColour);
            painter->setPen(kLabelColour);
            painter->drawText(QRectF(label.left(), bar.top(), label.width(), bar.height()), Qt::AlignLeft | Qt::AlignVCenter,
                              metrics.elidedText(warningLabel(w.kind), Qt::ElideRight, label.width()));
        } else {  // an outline only: it must not hide the bar and label it shares a level with
            painter->setPen(QPen(kLabelColour, 1.0, Qt::DotLine));
            painter->setBrush(Qt::NoBrush);
            painter->drawRect(bar);
        }
        *level = labelled ? occupiedTo : std::max(*level, right);
    }

    QRectF labelPlace(const QFontMetricsF& metrics, const QString& text, double left, double right) const
    {
        const LabelPlace place = warningLabelPlace(metrics.horizontalAdvance(text), metrics.horizontalAdvance(QStringLiteral("abcdef")),
                                                   left, right, lane_->rect().left(), lane_->rect().right());
        return QRectF(place.start, 0.0, place.width, 1.0);
    }

    /// The finding's span in pixels, at least 3 wide; nothing when it is out of view.
    std::optional<std::pair<double, double>> pixelSpan(const PlausibilityWarning& w) const
    {
        const QCPAxis* time = lane_->axis(QCPAxis::atBottom);
        if (w.end_s < time->range().lower || w.start_s > time->range().upper)
            return std::nullopt;
        const QRect area = lane_->rect();
        const double left = std::max(time->coordToPixel(w.start_s), static_cast<double>(area.left()));
        const double right = std::max(left + 3.0, std::min(time->coordToPixel(w.end_s), static_cast<double>(area.right())));
        return std::make_pair(left, right);
    }

    const WarningOverlay* overlay_;
    QCPAxisRect* lane_;
};

WarningOverlay::WarningOverlay(QCustomPlot* plot) : QObject(plot), plot_(plot)
{
    // Bands beneath the curves, above the grid and any stance shading already there.
    plot_->addLayer(kBandLayer, plot_->layer(QStringLiteral("main")), QCustomPlot::limBelow);
    connect(plot_, &QCustomPlot::mouseMove, this, &WarningOverlay::onMouseMove);
    connect(plot_, &QCustomPlot::beforeReplot, this, &WarningOverlay::fitLaneHeight);  // the plot may have been resized
}

void WarningOverlay::addRow(QCPAxisRect* rect)
{
    auto* bands = new TimeBands(rect, kBandColour);
    bands->setLayer(kBandLayer);
    rows_.push_back(rect);
    bands_.push_back(bands);
}

void WarningOverlay::setLane(QCPAxisRect* lane)
{
    lane_ = lane;
    rows_.push_back(lane);
    setUpLane(lane, tr("Warnings"));
    (new LaneBars(this, lane))->setLayer(QStringLiteral("main"));
}

void WarningOverlay::setWarnings(std::vector<PlausibilityWarning> warnings)
{
    warnings_ = std::move(warnings);
    const std::vector<QCPRange> spans = localSpans(warnings_);
    for (TimeBands* bands : bands_)
        bands->setSpans(spans);
    // One level more than the findings overlap: a label may run past its bar onto the next start.
    neededLevels_ = overlapDepth(warnings_) + 1;
    fitLaneHeight();
}

void WarningOverlay::fitLaneHeight()
{
    if (lane_ == nullptr)
        return;
    // As many levels as the findings need, within a fifth of the plot on screen: the signals come
    // first. A plot never shown (drawn for the report) has no height of its own yet.
    const double levelHeight = LaneBars::levelHeight(plot_);
    const auto fitting = plot_->isVisible()
                             ? static_cast<std::size_t>(std::max(0.0, std::floor(0.2 * plot_->height() / levelHeight)))
                             : kMaxLaneLevels;
    const std::size_t levels = std::clamp<std::size_t>(std::min(neededLevels_, fitting), 2, kMaxLaneLevels);
    const int height = static_cast<int>(std::ceil(static_cast<double>(levels) * levelHeight + 2.0));
    lane_->setMinimumSize(0, height);
    lane_->setMaximumSize(QWIDGETSIZE_MAX, height);
}

bool WarningOverlay::isShaded(double time_s) const
{
    return !bands_.empty() && bands_.front()->contains(time_s);
}

QString WarningOverlay::toolTipAt(double time_s) const
{
    std::vector<std::size_t> here;
    for (std::size_t i = 0; i < warnings_.size(); ++i)
        if (warnings_[i].start_s <= time_s && time_s <= warnings_[i].end_s)
            here.push_back(i);
    return warningsToolTip(warnings_, here);
}

void WarningOverlay::onMouseMove(QMouseEvent* event)
{
    const QPoint pos = event->position().toPoint();
    QString text;
    for (const QCPAxisRect* row : rows_)
        if (row->layout() != nullptr && row->rect().contains(pos))
            text = toolTipAt(row->axis(QCPAxis::atBottom)->pixelToCoord(pos.x()));
    if (!text.isEmpty()) {
        QToolTip::showText(event->globalPosition().toPoint(), text, plot_);
        toolTipShown_ = true;
    } else if (toolTipShown_) {
        QToolTip::hideText();
        toolTipShown_ = false;
    }
}

}  // namespace footpath
