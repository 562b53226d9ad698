#pragma once

#include "Result.h"
#include "nav/Parameters.h"

#include <QCoreApplication>
#include <QString>

#include <vector>

class QCPAbstractPlottable;
class QCPAxisRect;
class QCPGraph;
class QCustomPlot;

namespace footpath {

class DecimatedGraph;
class TimeBands;

/// StanceFlagsPlot's row of the detector's test statistic (StanceFlags::logStatistic) on a
/// logarithmic axis, with the threshold it was compared with at each sample (a moving line for
/// the adaptive threshold) and the stance shaded, so a user sees how far from stance each moment was.
class DetectorStatisticRow {
    // The texts keep the plot's translation context, where they were translated.
    Q_DECLARE_TR_FUNCTIONS(footpath::StanceFlagsPlot)

public:
    /// Makes rect's value axis logarithmic and adds the curves to plot, the shading on stanceLayer.
    DetectorStatisticRow(QCustomPlot* plot, QCPAxisRect* rect, const QString& stanceLayer);

    /// Plots result's statistic and threshold, framed in whole decades around them; none for nullptr.
    void plotStatistic(const Result* result);
    /// Shades result's stance; none for nullptr.
    void shadeStance(const Result* result);
    /// Names the axis, the statistic and the threshold after the detector params chooses;
    /// paperDetector: the C1/C2/C3 detector, which plots its C2 input here.
    void name(const Parameters& params, bool paperDetector);

    DecimatedGraph* statistic() const { return statistic_; }
    QCPGraph* threshold() const { return threshold_; }
    bool isStanceShaded(double time_s) const;
    /// What the legend names for this row: the threshold and the stance shading.
    std::vector<QCPAbstractPlottable*> legendEntries() const;

private:
    QCPAxisRect* rect_;
    DecimatedGraph* statistic_ = nullptr;
    QCPGraph* threshold_ = nullptr;
    QCPGraph* stanceLegendEntry_ = nullptr;  ///< draws nothing; gives the stance shading an entry
    TimeBands* stance_ = nullptr;
};

}  // namespace footpath
