#pragma once

#include "StanceFlagsPlot.h"

#include <QCoreApplication>

#include <array>
#include <vector>

class QCPAxisRect;
class QCPGraph;
class QCustomPlot;

namespace footpath {

/// StanceFlagsPlot's rows of the C1/C2/C3 detector's inputs, taken from the recording: |a|, the
/// centred std of |a| over the detector's window and |ω|, one row each, with the thresholds the
/// detector compares them with. Each row is framed to hold its thresholds and the bulk of its data.
class DetectorInputRows {
    // The texts keep the plot's translation context, where they were translated.
    Q_DECLARE_TR_FUNCTIONS(footpath::StanceFlagsPlot)

public:
    using Input = StanceFlagsPlot::Input;
    using Threshold = StanceFlagsPlot::Threshold;
    static constexpr std::size_t kInputCount = StanceFlagsPlot::kInputCount;
    static constexpr std::size_t kThresholdCount = StanceFlagsPlot::kThresholdCount;

    /// Adds the curves and threshold lines to plot, in rects (each input's row, in Input order).
    DetectorInputRows(QCustomPlot* plot, const std::array<QCPAxisRect*, kInputCount>& rects);

    /// Plots the recording's inputs (none for nullptr) and the thresholds across its time.
    void setRecording(const Recording* recording);
    /// Moves the thresholds, recomputes the std of |a| for a new window and frames the rows again.
    void setParameters(const Parameters& params);
    /// Frames each row around its thresholds and the bulk of its data.
    void rescale();

    /// The recording's sample times; empty without one.
    const std::vector<double>& times() const { return times_s_; }
    QCPGraph* graph(Input input) const;
    QCPGraph* threshold(Threshold threshold) const;
    const std::array<QCPGraph*, kThresholdCount>& thresholds() const { return thresholds_; }

private:
    void plotAccStdDev();
    void measure(Input input);
    void plotThresholds();
    QCPAxisRect* rectOf(Input input) const;

    /// Each row's (1 - kDataShare) and kDataShare quantiles, taken when its data is set: a
    /// parameter change rescales the rows without sorting a long walk's samples again.
    struct Bulk {
        double low = 0.0;
        double high = 0.0;
    };

    std::array<QCPAxisRect*, kInputCount> rects_;
    std::array<QCPGraph*, kInputCount> inputs_{};
    std::array<Bulk, kInputCount> bulk_{};
    std::array<QCPGraph*, kThresholdCount> thresholds_{};
    Parameters params_;
    std::vector<double> times_s_;
    std::vector<double> accNorm_;  ///< kept to recompute the std on a new window
};

}  // namespace footpath
