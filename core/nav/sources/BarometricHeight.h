#pragma once

#include "methods/MethodRegistry.h"
#include "nav/MeasurementSources.h"

#include <vector>

namespace footpath {

/// The pressure of one stance run, read robustly (shared by the height source and the motion
/// classes, so both see the same stance pressure).
struct StancePressure {
    double mean_pa = 0.0;   ///< Zheng et al. 2016 eq. 4: mean over the stance, spikes left out
    double first_pa = 0.0;  ///< mean of the run's first part ...
    double last_pa = 0.0;   ///< ... and of its last part (equal to mean_pa for short runs)
    bool spansHeightChange = false;  ///< long enough to tell first from last part (an elevator ride)
};

/// A height change inside one stance larger than this is an elevator ride. Far above the noise
/// (the two 0.5 s parts of a long ecg-xmu stance at rest differ by up to 0.3 m) and below any ride
/// (a floor is 2.5-4 m; a ride split over stances leaves the rest to the step-to-step rule).
constexpr double kMinStanceRide_m = 1.0;

/// Reads the pressures of one stance run (in time order, with their times). A sample more than a few
/// noise standard deviations from the median of its neighbours is a spike (the ecg-xmu files
/// have single-sample jumps of 50-90 Pa, 4-8 m, which no real motion produces in 10 ms) and is
/// left out. Runs of at least kMinRideStance_s also get the means of their first and last
/// kStancePart_s, so a ride inside one stance shows as a difference.
StancePressure readStancePressure(const std::vector<double>& times_s, const std::vector<double>& pressures_pa);

/// The pressures without spikes (each spike replaced by its neighbours' median).
std::vector<double> despikedPressure(const std::vector<double>& pressures_pa);

/// Zheng et al. 2016 (eq. 4-10 and 12-18): the barometric height of each stance - the
/// mean pressure over the stance run against the first stance's, as a height by
/// barometricHeight() - is a measurement of the position's z (dr_z, R = r_baro_m^2). It is formed
/// when the run ends, at the first sample after it, so the source stays causal.
///
/// The paper fuses it in a separate 2-state filter [h, v_z] driven by the vertical acceleration,
/// with zero vertical speed at ZUPT. The main filter's vertical channel is exactly that filter:
/// its z position and velocity are propagated with the vertical acceleration and ZUPT sets the
/// speed to zero at every stance, so the height is one more row on the same state, and the
/// barometer also corrects what the vertical channel is correlated with.
///
/// An elevator ride happens inside one stance: the detector sees a resting foot, ZUPT holds the
/// vertical speed at zero, and the inertial height does not follow the ride. Such a stance (its
/// first and last part differ by more than kMinStanceRide_m) gives the height of its last part,
/// the height now, with the measurement noise alone as its uncertainty: the inertial height has
/// no information about the ride, so the barometer resets it. Without pressure in the recording
/// the source leaves one note and does nothing.
class BarometricHeightSource : public MeasurementSource {
public:
    explicit BarometricHeightSource(const Parameters& params) : params_(params) {}
    const char* name() const override { return "baro"; }
    void apply(ErrorStateEkf& ekf, const SourceContext& context) override;
    void finish(double endTime_s, std::vector<MethodNote>& notes) override;

private:
    void stanceEnded(ErrorStateEkf& ekf);
    void updateHeight(ErrorStateEkf& ekf, double measuredZ_m, double noiseStd_m);

    Parameters params_;
    bool sawSample_ = false;
    bool hasPressure_ = true;
    double firstTime_s_ = 0.0;
    std::vector<double> runTimes_s_;
    std::vector<double> runPressures_pa_;
    bool haveReference_ = false;
    double referencePressure_pa_ = 0.0;
    double referenceZ_m_ = 0.0;
};

/// Its entry in the method registry (core/methods/MethodRegistry.h).
SourceMethod barometricHeightMethod();

}  // namespace footpath
