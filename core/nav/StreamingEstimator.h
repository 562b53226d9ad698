#pragma once

#include "Recording.h"
#include "Result.h"
#include "nav/Parameters.h"

#include <memory>
#include <string>

namespace footpath {

/// The pipeline of runPipeline, run causally on samples as they arrive (a live device).
///
/// The stance detector's centred windows look ahead: a sample's stance flag is final once samples
/// stanceDetectorLatency_s() later have arrived (window_half_s + median_window_s / 2 for the paper's
/// detector; the statistic window, half the adaptive window and the minimum stance for the others). The estimator holds each sample back
/// that long, then runs it through the EKF, so the estimate trails the newest sample by
/// a fixed latency (latency_s()) and never changes afterwards. The windows are found on the sample
/// times (the detector's causal form), so on a sample grid the hold-back may differ from latency_s() by
/// up to one sample interval, and the first sample after a gap longer than the latency releases
/// every sample before it. Alignment waits for the first alignment_s seconds (and their
/// look-ahead) before the first state appears; after a mid-walk start (see alignmentStart) it waits
/// for the first stance and the alignment_s after it, and the samples before that stance get the
/// start state.
///
/// After finish(), result() equals runPipeline on the same samples (runtime_s aside): the same
/// flags, states, steps and summary, value for value.
class StreamingEstimator {
public:
    explicit StreamingEstimator(const Parameters& params);
    ~StreamingEstimator();
    StreamingEstimator(const StreamingEstimator&) = delete;
    StreamingEstimator& operator=(const StreamingEstimator&) = delete;

    /// Empty when the parameters are valid; otherwise why nothing will be estimated. Also set by
    /// finish() when fewer than 2 samples arrived (runPipeline refuses those too).
    const std::string& error() const;

    /// Appends one sample. A sample not later than the previous one, or without a finite time,
    /// accelerometer or gyroscope value, is rejected and counted (rejectedSamples()): it would break
    /// the time windows or make every later state NaN. Estimates every
    /// sample whose stance decision became final. Does nothing while error() is set.
    void push(const ImuSample& sample);
    /// End of data: the remaining samples are decided with the windows truncated at the end, as
    /// runPipeline does, and estimated. Later push() calls are rejected and counted.
    void finish();

    /// The estimated samples: every per-sample vector (states and all flags) has the same length;
    /// steps hold the completed stance phases, summary what they give (runtime_s stays 0).
    const Result& result() const;
    /// Samples pushed but not yet estimated (look-ahead and, at the start, alignment).
    std::size_t pendingSamples() const;
    std::size_t rejectedSamples() const;
    /// True once the initial alignment ran and states are being produced.
    bool aligned() const;
    const Parameters& parameters() const;

    /// How far the estimate trails the newest sample while walking: stanceDetectorLatency_s().
    static double latency_s(const Parameters& params);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace footpath
