#pragma once

#include "Recording.h"
#include "Result.h"
#include "detect/StanceDetector.h"
#include "nav/ErrorStateEkf.h"
#include "nav/Parameters.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace footpath {


/// What a measurement source sees at one sample, after the filter has propagated to it.
struct SourceContext {
    const ImuSample& sample;
    std::size_t index = 0;            ///< samples since the start of the recording
    const SampleStanceFlags& flags;   ///< the detector's decision and statistic for this sample
    std::vector<MethodNote>& notes;   ///< where a source says what it did or skipped, with the span
};

/// One measurement of the error-state filter (ZUPT/ZARU, HDR, IPER, ZUNA, barometer, magnetometer):
/// it decides from the sample, the stance flags and its own history whether its condition holds
/// and, if so, updates the filter. Causal: it sees the samples in order and nothing later, so the
/// live estimator uses the same sources as the offline pipeline.
class MeasurementSource {
public:
    virtual ~MeasurementSource() = default;
    /// Stable short name for notes and comparisons ("hdr").
    virtual const char* name() const = 0;
    virtual void apply(ErrorStateEkf& ekf, const SourceContext& context) = 0;
    /// At the end of the recording: close any open span in the notes.
    virtual void finish(double /*endTime_s*/, std::vector<MethodNote>& /*notes*/) {}
};

/// The sources the parameters switch on, in the order they are applied at each sample (the
/// registry's applyRank; a new source is added in core/methods/SourceMethods.cpp).
class MeasurementSources {
public:
    explicit MeasurementSources(const Parameters& params);
    ~MeasurementSources();
    MeasurementSources(MeasurementSources&&) noexcept;
    MeasurementSources& operator=(MeasurementSources&&) noexcept;

    void apply(ErrorStateEkf& ekf, const SourceContext& context);
    void finish(double endTime_s, std::vector<MethodNote>& notes);
    std::size_t size() const { return sources_.size(); }

private:
    /// What the innovation gate did to one source's measurements.
    struct GateTally {
        std::size_t tested = 0;
        std::size_t rejected = 0;
        double firstRejected_s = std::nan("");
        double lastRejected_s = std::nan("");
        void add(const ErrorStateEkf::GateCounts& before, const ErrorStateEkf::GateCounts& after, double time_s);
    };

    std::vector<std::unique_ptr<MeasurementSource>> sources_;
    std::vector<GateTally> gates_;  ///< one per source
    double gateProbability_ = 0.0;
};

}  // namespace footpath
