#pragma once

#include "methods/MethodRegistry.h"
#include "nav/MeasurementSources.h"
#include "nav/sources/SourceSupport.h"

#include <deque>

namespace footpath {

/// HDR (heuristic drift reduction) of the five-method EKF paper: on a straight stretch the heading should not change,
/// so the heading change the filter shows there is drift and goes in as a yaw-only measurement.
///
/// Read differently from the paper, and why:
/// - Once per stance, not at every sample: the foot's yaw swings during the swing phase, so the
///   sliding comparison at every sample would call the foot's own rotation drift; and the filter
///   takes each update as independent evidence.
/// - Straight or turning is decided from the gyro-integrated heading (the rate rotated to the
///   navigation frame, without this or any other correction), comparing the stance now with the
///   stance hdr_lag_s ago. With the filter's yaw, HDR's own pull would hide a slow turn from it.
/// - The reference is the heading held from the start of the straight stretch, not the sliding
///   heading lambda ago: a sliding reference follows the drift (each update only removes the
///   drift of one lag). The stretch ends when the gyro heading has moved hdr_threshold_rad from
///   the stretch's start, so a slow curve that passes the sliding test is fought by at most that
///   much before the reference restarts.
class HeadingDriftReductionSource : public MeasurementSource {
public:
    explicit HeadingDriftReductionSource(const Parameters& params) : params_(params) {}
    const char* name() const override { return "hdr"; }
    void apply(ErrorStateEkf& ekf, const SourceContext& context) override;

private:
    struct StanceHeading {
        double time_s;
        double gyroHeading_rad;  ///< integrated rate, no corrections
        double yaw_rad;          ///< the filter's heading
    };
    void integrateGyroHeading(const ErrorStateEkf& ekf, const ImuSample& sample);
    const StanceHeading* stanceLagAgo(double time_s) const;

    Parameters params_;
    sources::StanceTrigger trigger_{0.03};
    double gyroHeading_rad_ = 0.0;
    double previousTime_s_ = std::nan("");
    std::deque<StanceHeading> history_;
    bool stretchOpen_ = false;
    StanceHeading stretchStart_{0.0, 0.0, 0.0};
};

/// Its entry in the method registry (core/methods/MethodRegistry.h).
SourceMethod headingDriftReductionMethod();

}  // namespace footpath
