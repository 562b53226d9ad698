#pragma once

#include "Recording.h"

#include <QCoreApplication>
#include <QString>

#include <optional>
#include <vector>

class QCPAxisRect;
class QCPGraph;
class QCustomPlot;

namespace footpath {

class TimeBands;

/// StanceFlagsPlot's lane of the recording's reference stance (IPOL gait events, pyshoe's
/// zv_vicon_opt): a shaded step curve under the detector's lanes, to compare the detector with.
class ReferenceStanceLane {
    // The texts keep the plot's translation context, where they were translated.
    Q_DECLARE_TR_FUNCTIONS(footpath::StanceFlagsPlot)

public:
    /// Makes rect the lane and adds its curve to plot.
    ReferenceStanceLane(QCustomPlot* plot, QCPAxisRect* rect);

    /// Shows recording's reference stance at its sample times (nothing for nullptr or none).
    void setRecording(const Recording* recording, const std::vector<double>& times);
    /// Whether the recording has a reference stance: the lane is in the layout only then.
    bool hasStance() const;
    bool isStance(double time_s) const;
    /// Where the reference stance comes from, for the lane's tool tip; empty without one.
    const QString& source() const { return source_; }
    /// "stance" or "swing" for the lane's curve at value, as the hover readout names it; nothing
    /// for another graph.
    std::optional<QString> readout(const QCPGraph* graph, double value) const;

private:
    QCPGraph* curve_ = nullptr;  ///< step curve of the reference stance
    TimeBands* fill_ = nullptr;
    QString source_;
};

}  // namespace footpath
