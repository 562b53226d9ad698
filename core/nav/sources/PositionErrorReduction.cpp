#include "nav/sources/PositionErrorReduction.h"

#include "methods/SourceMethodSupport.h"
#include "nav/ErrorStateEkf.h"

#include <QtGlobal>

#include <cmath>
#include <cstdio>

namespace footpath {

namespace {

constexpr double kMinStride_m = 0.3;        ///< a shorter move between stances is no stride
constexpr int kStridesForAxis = 6;          ///< strides before the automatic axis is trusted
constexpr double kMinConcentration = 0.5;   ///< resultant length of the 4x directions

std::string degrees(double angle_rad)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.0f deg", angle_rad * 180.0 / M_PI);
    return text;
}

}  // namespace

void PositionErrorReductionSource::addStride(const Eigen::Vector2d& stride_m)
{
    const double length = stride_m.norm();
    directionSum_ += length * std::polar(1.0, 4.0 * std::atan2(stride_m.y(), stride_m.x()));
    strideLengthSum_m_ += length;
    ++strides_;
}

std::optional<double> PositionErrorReductionSource::buildingAxis(std::string& whyNot) const
{
    if (!params_.iper_axis_auto)
        return params_.iper_axis_rad;
    if (strides_ < kStridesForAxis) {
        whyNot = "not applied: building axis not estimated yet (fewer than " + std::to_string(kStridesForAxis) +
                 " strides)";
        return std::nullopt;
    }
    const double concentration = std::abs(directionSum_) / strideLengthSum_m_;
    if (concentration < kMinConcentration) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "not applied: the stride directions do not follow a rectilinear building "
                      "(concentration modulo 90 deg %.2f < %.2f)",
                      concentration, kMinConcentration);
        whyNot = text;
        return std::nullopt;
    }
    return std::arg(directionSum_) / 4.0;
}

std::optional<double> PositionErrorReductionSource::followedDirection(double axis_rad, const Eigen::Vector2d& stride_m) const
{
    const double heading = std::atan2(stride_m.y(), stride_m.x());
    const double quarter = M_PI / 2.0;
    const double direction = axis_rad + quarter * std::round(sources::wrapAngle(heading - axis_rad) / quarter);
    if (std::abs(sources::wrapAngle(heading - direction)) > params_.iper_threshold_rad)
        return std::nullopt;
    return sources::wrapAngle(direction);
}

void PositionErrorReductionSource::updateCrossAxis(ErrorStateEkf& ekf, const Eigen::Vector2d& position_m) const
{
    // Unit vector across the stretch's direction; the offset from the stretch's start along it is
    // the error (z = n . dr, dr = estimate - truth).
    const Eigen::Vector2d across(-std::sin(stretchDirection_rad_), std::cos(stretchDirection_rad_));
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(1, ErrorStateEkf::kStates);
    h(0, ErrorStateEkf::kPos) = across.x();
    h(0, ErrorStateEkf::kPos + 1) = across.y();
    const double offset = across.dot(position_m - stretchStart_.position_m);
    ekf.updateRows(h, Eigen::VectorXd::Constant(1, offset), Eigen::VectorXd::Constant(1, params_.r_iper_m * params_.r_iper_m));
}

void PositionErrorReductionSource::updateHeight(ErrorStateEkf& ekf) const
{
    // Level floor: the start height (0) at every stance.
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(1, ErrorStateEkf::kStates);
    h(0, ErrorStateEkf::kPos + 2) = 1.0;
    const double variance = params_.r_iper_height_m * params_.r_iper_height_m;
    ekf.updateRows(h, Eigen::VectorXd::Constant(1, ekf.state().position_m.z()), Eigen::VectorXd::Constant(1, variance));
}

void PositionErrorReductionSource::apply(ErrorStateEkf& ekf, const SourceContext& context)
{
    if (!trigger_.fires(context.flags.stance, context.sample.time_s))
        return;
    if (!params_.use_baro)
        updateHeight(ekf);
    const Stance now{context.sample.time_s, ekf.state().position_m.head<2>()};
    if (!previous_) {
        previous_ = now;
        return;
    }
    const Eigen::Vector2d stride = now.position_m - previous_->position_m;
    if (stride.norm() < kMinStride_m)
        return;  // standing: the stretch and its reference stay as they are
    addStride(stride);
    std::string whyNot;
    const std::optional<double> axis = buildingAxis(whyNot);
    const std::optional<double> direction = axis ? followedDirection(*axis, stride) : std::nullopt;
    if (axis && !direction)
        whyNot = "not applied: walking off the building's axes (axis " + degrees(*axis) + ", threshold " +
                 degrees(params_.iper_threshold_rad) + ")";
    // The same axis direction as the stretch so far (the automatic axis moves a little per stride).
    const bool continues =
        direction && stretchOpen_ && std::abs(sources::wrapAngle(*direction - stretchDirection_rad_)) < M_PI / 4.0;
    if (direction && !continues) {
        stretchOpen_ = true;
        stretchStart_ = *previous_;
    }
    if (direction)
        stretchDirection_rad_ = *direction;
    else
        stretchOpen_ = false;
    previous_ = now;
    if (!whyNot.empty()) {
        // The span splits by the reason's kind (the text before the figures), not by its figures.
        notes_.mark(now.time_s, whyNot.substr(0, whyNot.find('(')), context.notes);
        notes_.detail(whyNot);
        return;
    }
    if (now.time_s - stretchStart_.time_s < params_.iper_window_s)
        return;  // along an axis, but not yet for a whole window
    notes_.mark(now.time_s, {}, context.notes);
    updateCrossAxis(ekf, now.position_m);
}

void PositionErrorReductionSource::finish(double endTime_s, std::vector<MethodNote>& notes)
{
    notes_.finish(endTime_s, notes);
}


// ---- registry entry (core/methods/SourceMethods.cpp lists it) ----------------------------

namespace {

const FieldCondition iperOn{"iper", methods::switchIsOn<&Parameters::use_iper>,
    QT_TRANSLATE_NOOP("footpath::ParameterPanel", "Not used: IPER is off (use_iper).")};
const FieldCondition iperFixedAxis{"iper_fixed_axis", [](const Parameters& p) { return !p.iper_axis_auto; },
                                  QT_TRANSLATE_NOOP("footpath::ParameterPanel",
                                                    "Not used: the axis is estimated from the walk (iper_axis_auto is on)."),
                                  &iperOn};

}  // namespace

SourceMethod positionErrorReductionMethod()
{
    const auto fields = [] {
        using P = Parameters;
        return std::vector<ParameterField>{
            flagField("use_iper", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Position error reduction (IPER)"),
                 &P::use_iper,
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Position error reduction: walks along the building's axes, level floor ("
                                   "assumes a rectilinear building)"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
            flagField("iper_axis_auto", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Building axis from the walk"),
                 &P::iper_axis_auto,
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "IPER: building axis from the walk's dominant directions"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER"), &iperOn),
            realField("iper_axis_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Building axis angle"),
                 &P::iper_axis_rad, -M_PI, M_PI, "rad",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER: angle of the building's main axis from x"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER"), &iperFixedAxis),
            realField("iper_threshold_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Along-axis tolerance"),
                 &P::iper_threshold_rad, 0.0, 0.8, "rad",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "IPER: walking within this of an axis counts as along it"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER"), &iperOn),
            realField("iper_window_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER window"), &P::iper_window_s, 0.2,
                 30.0, "s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER: displacement window"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER"), &iperOn),
            realField("r_iper_m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER cross-axis std"), &P::r_iper_m, 1e-6,
                 10.0, "m",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER: R of the cross-axis displacement, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER"), &iperOn),
            realField("r_iper_height_m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER level-floor height std"),
                 &P::r_iper_height_m, 1e-6, 10.0, "m",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER: R of the level-floor height, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER"), &iperOn),
        };
    };
    return {"iper", "IPER", "use_iper", methods::switchIsOn<&Parameters::use_iper>, methods::setSwitch<&Parameters::use_iper>,
            methods::makeWhenOn<PositionErrorReductionSource, &Parameters::use_iper>, fields, 50};
}

}  // namespace footpath
