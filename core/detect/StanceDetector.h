#pragma once

#include "Recording.h"
#include "Result.h"
#include "nav/Parameters.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <vector>

namespace footpath {

/// The stance flags of the chosen detector (params.detector): the paper's C1/C2/C3 detector below, or
/// one of the statistic detectors of detect/StatisticDetectors.h. Offline and non-causal.
StanceFlags detectStance(const std::vector<ImuSample>& samples, const Parameters& params);

/// Told that the flags of the first decidedSamples samples are final; returns false to stop.
using DecidedCallback = std::function<bool(std::size_t decidedSamples)>;

/// detectStance into flags, calling decided each time more leading samples' flags are final (the
/// statistic detectors every batch of samples, the paper's detector once), the last time with
/// samples.size(). A reader on another thread may use the flags decided so far while the rest are
/// being decided (runPipeline runs the filter behind the detector): from the first call on, flags
/// keep their size and storage. Returns false if decided said stop.
bool detectStanceInto(const std::vector<ImuSample>& samples, const Parameters& params, StanceFlags& flags,
                      const DecidedCallback& decided);

/// Guo 2015 section 2.3: C1 (|a| within [acc_min, acc_max]), C2 (std of |a| over the centred
/// window below acc_std_max; the paper's text says "above", eq. 20 and the physics say below),
/// C3 (|w| below gyr_max), C = C1 & C2 & C3, then a median filter. Windows are durations, found
/// from the timestamps, so 100 Hz and 200 Hz recordings behave the same and gaps are honoured.
/// Offline and non-causal: the centred windows look ahead by window_half_s + median_window_s / 2.
/// logStatistic is log10 of the std of |a| (C2's input), logThreshold log10 of acc_std_max_mps2.
StanceFlags detectPaperStance(const std::vector<ImuSample>& samples, const Parameters& params);

/// Centred sliding standard deviation of values over samples with |t_j - t_k| <= halfWindow_s.
/// Near the ends the window holds only the samples that exist.
std::vector<double> centredStdDev(const std::vector<double>& times, const std::vector<double>& values,
                                  double halfWindow_s);

/// Binary median (majority vote) over samples with |t_j - t_k| <= window_s / 2; a tie keeps the
/// input value.
std::vector<std::uint8_t> medianFilter(const std::vector<double>& times, const std::vector<std::uint8_t>& flags,
                                       double window_s);

/// The detector's flags of one sample: one entry of each vector of StanceFlags.
struct SampleStanceFlags {
    std::uint8_t c1 = 0;
    std::uint8_t c2 = 0;
    std::uint8_t c3 = 0;
    std::uint8_t c = 0;
    std::uint8_t stance = 0;
    float logStatistic = 0.0f;
    float logThreshold = 0.0f;
};

/// Appends one sample's flags to the per-sample vectors.
void appendFlags(StanceFlags& flags, const SampleStanceFlags& sample);

/// Sizes every per-sample vector for count samples.
void resizeFlags(StanceFlags& flags, std::size_t count);

/// Stores sample k's flags in vectors already sized past it (inline: the offline detectors call it
/// once a sample).
inline void setFlags(StanceFlags& flags, std::size_t k, const SampleStanceFlags& sample)
{
    flags.c1[k] = sample.c1;
    flags.c2[k] = sample.c2;
    flags.c3[k] = sample.c3;
    flags.c[k] = sample.c;
    flags.stance[k] = sample.stance;
    flags.logStatistic[k] = sample.logStatistic;
    flags.logThreshold[k] = sample.logThreshold;
}

/// Sample k's entry of each per-sample vector.
inline SampleStanceFlags flagsAt(const StanceFlags& flags, std::size_t k)
{
    SampleStanceFlags sample;
    sample.c1 = flags.c1[k];
    sample.c2 = flags.c2[k];
    sample.c3 = flags.c3[k];
    sample.c = flags.c[k];
    sample.stance = flags.stance[k];
    sample.logStatistic = flags.logStatistic[k];
    sample.logThreshold = flags.logThreshold[k];
    return sample;
}

/// A stance detector run causally, on samples as they arrive: each sample's flags are handed out
/// once they are final, oldest first, and never change. Every detector is one of these, so a live
/// device gets the same detectors as a file.
class CausalStanceDecider {
public:
    virtual ~CausalStanceDecider() = default;
    /// Takes the next sample; its time must be later than the previous one's (the caller checks).
    /// Appends to decided the flags that became final, oldest first.
    virtual void push(const ImuSample& sample, std::deque<SampleStanceFlags>& decided) = 0;
    /// End of data: appends the flags of every sample not yet decided.
    virtual void finish(std::deque<SampleStanceFlags>& decided) = 0;
};

/// The causal form of params.detector.
std::unique_ptr<CausalStanceDecider> makeCausalStanceDetector(const Parameters& params);
/// How far the chosen detector's decision trails the newest sample.
double stanceDetectorLatency_s(const Parameters& params);

/// detectPaperStance run causally, on samples as they arrive (a live device). A sample's flags become
/// final once the samples that close its windows have arrived: its median window
/// (median_window_s / 2 ahead) and the C2 window (window_half_s) of every sample in it, both found
/// on the sample times, so the decision trails the newest sample by about window_half_s +
/// median_window_s / 2. finish() decides the rest with the windows truncated at the end of data.
/// Over a whole recording the flags equal detectPaperStance's value for value: the same prefix sums
/// (kept as running totals) and the same window arithmetic. Only the samples some open window
/// still needs are kept, so memory is bounded by the window lengths.
class CausalStanceDetector : public CausalStanceDecider {
public:
    explicit CausalStanceDetector(const Parameters& params);

    void push(const ImuSample& sample, std::deque<SampleStanceFlags>& decided) override;
    void finish(std::deque<SampleStanceFlags>& decided) override;

    /// Samples whose flags were handed out.
    std::size_t decidedSamples() const { return stanceNext_; }
    /// Samples held: those windows still open need, plus at most as many (or kMinimumDrop)
    /// waiting to be dropped in one go.
    std::size_t bufferedSamples() const { return entries_.size(); }
    static constexpr std::size_t kMinimumDrop = 64;

private:
    struct Entry {
        double time_s = 0.0;
        double sumBefore = 0.0;    ///< prefix sums of the shifted |a| over the samples before this one
        double sumSqBefore = 0.0;
        std::size_t onesBefore = 0;  ///< c flags set before this one; valid once its c2 is decided
        SampleStanceFlags flags;
    };

    std::size_t received() const { return base_ + entries_.size(); }
    const Entry& at(std::size_t k) const { return entries_[k - base_]; }
    Entry& at(std::size_t k) { return entries_[k - base_]; }
    double sumBefore(std::size_t k) const;
    double sumSqBefore(std::size_t k) const;
    std::size_t onesBefore(std::size_t k) const;

    void decide(bool endOfData, std::deque<SampleStanceFlags>& decided);
    bool decideNextC2(bool endOfData);
    bool decideNextStance(bool endOfData, std::deque<SampleStanceFlags>& decided);
    void dropSamplesNoWindowNeeds();

    Parameters params_;
    std::vector<Entry> entries_;
    std::size_t base_ = 0;  ///< index of entries_.front() in the whole stream
    double shift_ = 0.0;    ///< |a| of the first sample, as centredStdDev shifts by values.front()
    double sum_ = 0.0;      ///< prefix sums over every sample received
    double sumSq_ = 0.0;
    std::size_t ones_ = 0;  ///< c flags set among the samples before c2Next_
    // Indices in the whole stream: the next sample to decide and its window [first, last), for
    // C2 and for the median. Like detectStance's, the windows only move forward.
    std::size_t c2Next_ = 0;
    std::size_t c2First_ = 0;
    std::size_t c2Last_ = 0;
    std::size_t stanceNext_ = 0;
    std::size_t medianFirst_ = 0;
    std::size_t medianLast_ = 0;
};

}  // namespace footpath
