#pragma once

#include "MotionLanes.h"
#include "PlotInteraction.h"
#include "Result.h"
#include "WarningOverlay.h"
#include "gait/GaitEvents.h"

#include <QAbstractTableModel>
#include <QCoreApplication>
#include <QLocale>

#include <memory>
#include <vector>

namespace footpath {

/// One row per stance phase. Display text is formatted; kSortRole holds the number so sorting is
/// numeric.
class StepTableModel : public QAbstractTableModel {
    // The texts keep the summary panel's translation context, where they were translated.
    Q_DECLARE_TR_FUNCTIONS(footpath::SummaryPanel)

public:
    enum Column { Number, StanceStart, StanceEnd, StanceDuration, StrideLength, StrideDuration, X, Y, Z, Motion, BaroHeight,
                  HeelStrike, ToeOff, GaitStancePct, Clearance, ColumnCount };
    static constexpr int kSortRole = Qt::UserRole;

    using QAbstractTableModel::QAbstractTableModel;

    void setResult(std::shared_ptr<const Result> result)
    {
        beginResetModel();
        result_ = std::move(result);
        stepWarnings_.clear();
        for (std::size_t step = 0; result_ && step < result_->steps.size(); ++step)
            stepWarnings_.push_back(warningsOfStep(*result_, step));
        gaitStrides_ = result_ ? gaitStridesOfSteps(*result_) : std::vector<const GaitStride*>();
        endResetModel();
    }

    /// Whether a warning's span overlaps the stride that ends with this step.
    bool isMarked(int row) const { return !stepWarnings_.at(static_cast<std::size_t>(row)).empty(); }
    double stanceStart(int row) const { return result_->steps.at(static_cast<std::size_t>(row)).stanceStart_s; }

    int rowCount(const QModelIndex& parent = {}) const override
    {
        // The steps at the last setResult: a live path grows in place between refreshes.
        return parent.isValid() || !result_ ? 0 : static_cast<int>(stepWarnings_.size());
    }
    int columnCount(const QModelIndex& parent = {}) const override { return parent.isValid() ? 0 : ColumnCount; }

    QVariant data(const QModelIndex& index, int role) const override
    {
        if (!index.isValid() || !result_)
            return {};
        if (role == Qt::TextAlignmentRole)
            return QVariant(Qt::AlignRight | Qt::AlignVCenter);
        if (const QVariant marking = warningMarking(index, role); marking.isValid())
            return marking;
        if (index.column() == Motion && role != kSortRole)
            return motionData(index.row(), role);
        const double value = valueAt(index.row(), index.column());
        if (role == kSortRole)
            return value;
        if (role != Qt::DisplayRole)
            return {};
        const bool noStride = index.row() == 0 && (index.column() == StrideLength || index.column() == StrideDuration);
        return noStride ? QStringLiteral("\u2013") : formatFigure(value, decimalsOf(index.column()), QLocale());
    }

    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override
    {
        if (orientation != Qt::Horizontal)
            return {};
        if (role == Qt::DisplayRole)
            return title(section);
        if (role == Qt::ToolTipRole)
            return toolTip(section);
        return {};
    }

private:
    /// A marked row: light red, a warning icon before the step number, the messages as tool tip.
    QVariant warningMarking(const QModelIndex& index, int role) const
    {
        if (!isMarked(index.row()))
            return {};
        switch (role) {
        case Qt::BackgroundRole: return QColor(255, 222, 212);
        case Qt::ForegroundRole: return QColor(Qt::black);  // readable on the light red in a dark theme too
        case Qt::ToolTipRole:
            return warningsToolTip(result_->warnings, stepWarnings_[static_cast<std::size_t>(index.row())]);
        case Qt::DecorationRole:
            return index.column() == Number ? QApplication::style()->standardIcon(QStyle::SP_MessageBoxWarning) : QVariant();
        default: return {};
        }
    }

    /// The class's name with its colour as a swatch (as in the lane and the paths).
    QVariant motionData(int row, int role) const
    {
        const MotionClass motion = result_->steps.at(static_cast<std::size_t>(row)).motion;
        if (role == Qt::DisplayRole)
            return motion == MotionClass::Unknown ? QStringLiteral("\u2013") : motionClassLabel(motion);
        if (role == Qt::DecorationRole && motion != MotionClass::Unknown)
            return motionClassColour(motion);
        return {};
    }

    double valueAt(int row, int column) const
    {
        const Step& step = result_->steps[static_cast<std::size_t>(row)];
        switch (column) {
        case Number: return row + 1;
        case StanceStart: return step.stanceStart_s;
        case StanceEnd: return step.stanceEnd_s;
        case StanceDuration: return step.stanceEnd_s - step.stanceStart_s;
        case StrideLength: return step.strideLength_m;
        case StrideDuration: return step.strideDuration_s;
        case X: return step.position_m.x();
        case Y: return step.position_m.y();
        case Z: return step.position_m.z();
        case Motion: return static_cast<int>(step.motion);
        case BaroHeight: return step.baroHeight_m;
        default: return gaitValueAt(row, column);
        }
    }

    /// The gait stride's figures (heel strike to toe off); NaN, shown as a dash, without a stride.
    double gaitValueAt(int row, int column) const
    {
        const GaitStride* stride = gaitStrides_[static_cast<std::size_t>(row)];
        if (!stride)
            return std::numeric_limits<double>::quiet_NaN();
        switch (column) {
        case HeelStrike: return stride->heelStrike.time_s;
        case ToeOff: return stride->toeOff.time_s;
        case GaitStancePct: return stride->stancePct;
        case Clearance: return stride->clearance_m;
        default: return 0.0;
        }
    }

    static int decimalsOf(int column)
    {
        // Times to a millisecond (a 200 Hz sample is 5 ms), positions to a centimetre.
        switch (column) {
        case Number: return 0;
        case GaitStancePct: return 1;
        case HeelStrike:
        case ToeOff:
        case Clearance: return 3;
        default: return column >= X ? 2 : 3;
        }
    }

    static QString title(int column)
    {
        switch (column) {
        case Number: return tr("Step");
        case StanceStart: return tr("Start (s)");
        case StanceEnd: return tr("End (s)");
        case StanceDuration: return tr("Stance (s)");
        case StrideLength: return tr("Stride (m)");
        case StrideDuration: return tr("Stride time (s)");
        case X: return tr("x (m)");
        case Y: return tr("y (m)");
        case Z: return tr("z (m)");
        case Motion: return MotionLanes::tr("Motion");
        case BaroHeight: return MotionLanes::tr("Baro height (m)");
        case HeelStrike: return tr("Heel strike (s)");
        case ToeOff: return tr("Toe off (s)");
        case GaitStancePct: return tr("Gait stance (%)");
        case Clearance: return tr("Clearance (m)");
        default: return {};
        }
    }

    static QString toolTip(int column)
    {
        switch (column) {
        case StanceStart: return tr("When the foot came to rest");
        case StanceEnd: return tr("When the foot lifted off");
        case StanceDuration: return tr("How long the foot was at rest");
        case StrideLength: return tr("Horizontal distance from the previous stance");
        case StrideDuration: return tr("Time from the previous stance start to this one");
        case X:
        case Y:
        case Z: return tr("Mean position during the stance, relative to the start");
        case Motion: return MotionLanes::tr("How the foot got to this step: level, stairs or elevator (from the barometer)");
        case BaroHeight: return MotionLanes::tr("Barometric height at this stance against the first one");
        case HeelStrike: return tr("The gait stride whose stance holds this step: when the foot landed");
        case ToeOff: return tr("When the foot left the ground (the end of the gait lab's stance)");
        case GaitStancePct: return tr("Heel strike to toe off, % of the stride time");
        case Clearance: return tr("Highest point of the swing after this stance above it");
        default: return {};
        }
    }

    std::shared_ptr<const Result> result_;
    std::vector<std::vector<std::size_t>> stepWarnings_;  ///< per step: indices into result_->warnings
    std::vector<const GaitStride*> gaitStrides_;  ///< per step: its gait stride or null (gaitStridesOfSteps)
};

}  // namespace footpath
