#pragma once

#include "methods/MethodRegistry.h"
#include "nav/MeasurementSources.h"
#include "nav/sources/SourceSupport.h"

#include <complex>
#include <optional>

namespace footpath {

/// IPER (investigative position error reduction) of the five-method EKF paper. It assumes a rectilinear building and a
/// level floor: on a straight stretch along one of the building's axes the displacement across the
/// axis is an error, and at every stance the height should be the start height.
///
/// Read differently from the paper, and why:
/// - Evaluated once per stance from the stance positions (the foot's position is only meaningful
///   at rest). A stretch is a run of strides each within iper_threshold_rad of the same axis
///   direction; once it has lasted iper_window_s, each further stance measures its cross-axis
///   offset from the stretch's start (the paper's fixed window measures it from the window's start,
///   which forgives the drift of every earlier window).
/// - With iper_axis_auto the axis comes from the strides so far: the length-weighted circular mean
///   of the stride directions taken four times (directions modulo 90 deg), used once a few strides
///   exist and only when they concentrate (a circle spreads them and IPER stays off).
/// - The level-floor height is not measured when the barometer is on (it knows the floor).
class PositionErrorReductionSource : public MeasurementSource {
public:
    explicit PositionErrorReductionSource(const Parameters& params) : params_(params) {}
    const char* name() const override { return "iper"; }
    void apply(ErrorStateEkf& ekf, const SourceContext& context) override;
    void finish(double endTime_s, std::vector<MethodNote>& notes) override;

private:
    struct Stance {
        double time_s;
        Eigen::Vector2d position_m;
    };
    std::optional<double> buildingAxis(std::string& whyNot) const;
    void addStride(const Eigen::Vector2d& stride_m);
    /// The axis direction (axis + k 90 deg) a stride follows, or none.
    std::optional<double> followedDirection(double axis_rad, const Eigen::Vector2d& stride_m) const;
    void updateCrossAxis(ErrorStateEkf& ekf, const Eigen::Vector2d& position_m) const;
    void updateHeight(ErrorStateEkf& ekf) const;

    Parameters params_;
    sources::StanceTrigger trigger_{0.03};
    sources::SpanNotes notes_{"iper"};
    std::optional<Stance> previous_;
    std::complex<double> directionSum_ = 0.0;  ///< sum of |stride| exp(4 i heading)
    double strideLengthSum_m_ = 0.0;
    int strides_ = 0;
    bool stretchOpen_ = false;
    Stance stretchStart_{0.0, Eigen::Vector2d::Zero()};
    double stretchDirection_rad_ = 0.0;
};

/// Its entry in the method registry (core/methods/MethodRegistry.h).
SourceMethod positionErrorReductionMethod();

}  // namespace footpath
