#include "nav/Parameters.h"

#include <QtGlobal>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace footpath {

namespace {

using K = ParameterField::Kind;

ParameterField real(const char* name, const char* label, double Parameters::*member, double lo, double hi,
                    const char* unit, const char* description, const char* group, FieldScope scope = FieldScope::Always)
{
    ParameterField field{name, K::Real, member, nullptr, lo, hi, unit, description, group};
    field.label = label;
    field.scope = scope;
    return field;
}

ParameterField flag(const char* name, const char* label, bool Parameters::*member, const char* description,
                    const char* group, FieldScope scope = FieldScope::Always)
{
    ParameterField field{name, K::Flag, nullptr, member, 0.0, 1.0, "", description, group};
    field.label = label;
    field.scope = scope;
    return field;
}

ParameterField choice(const char* name, const char* label, int Parameters::*member, std::vector<const char*> names,
                      std::vector<const char*> labels, const char* description, const char* group,
                      FieldScope scope = FieldScope::Always)
{
    ParameterField field{name, K::Choice, nullptr, nullptr, 0.0, static_cast<double>(names.size() - 1), "",
                         description, group};
    field.label = label;
    field.choice = member;
    field.choiceNames = std::move(names);
    field.choiceLabels = std::move(labels);
    field.scope = scope;
    return field;
}

// Labels, descriptions, groups and choice labels are marked for translation (QT_TRANSLATE_NOOP
// leaves the literal as it is): the parameter panel shows them translated under this context.
std::vector<ParameterField> makeFields()
{
    using P = Parameters;
    return {
            real("alignment_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Alignment period"), &P::alignment_s,
                 0.05, 600.0, "s",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Static period at the start used for alignment"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Alignment")),
            real("gravity_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Gravity"), &P::gravity_mps2, 9.7, 9.9,
                 "m/s^2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Local gravity"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Alignment")),
            real("declination_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetic declination"),
                 &P::declination_rad, -M_PI, M_PI, "rad",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Magnetic declination subtracted from the compass heading"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Alignment")),
            choice("detector", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Stance detector"), &P::detector,
                   {"c1c2c3", "shoe", "ared", "amvd", "mbgtd"},
                   {QT_TRANSLATE_NOOP("footpath::ParameterFields", "C1/C2/C3 (Guo 2015)"),
                    QT_TRANSLATE_NOOP("footpath::ParameterFields", "SHOE (GLRT)"),
                    QT_TRANSLATE_NOOP("footpath::ParameterFields", "ARED (angular rate energy)"),
                    QT_TRANSLATE_NOOP("footpath::ParameterFields", "AMVD (acceleration variance)"),
                    QT_TRANSLATE_NOOP("footpath::ParameterFields", "MBGTD (graph theoretic)")},
                   QT_TRANSLATE_NOOP("footpath::ParameterFields", "Statistic that decides the foot is at rest"),
                   QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector")),
            real("zv_window_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Statistic window"), &P::zv_window_s,
                 0.0, 1.0, "s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Window of the detector statistic"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::StatisticDetectors),
            real("zv_sigma_acc_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Accelerometer noise"),
                 &P::zv_sigma_acc_mps2, 1e-5, 10.0, "m/s^2",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Accelerometer noise the statistic is normalised by"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::DetectorAccelerometer),
            real("zv_sigma_gyr_radps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Gyroscope noise"),
                 &P::zv_sigma_gyr_radps, 1e-6, 1.0, "rad/s",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Gyroscope noise the statistic is normalised by"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::DetectorGyroscope),
            flag("zv_adaptive", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Adaptive threshold"), &P::zv_adaptive,
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Threshold follows the motion (off: a fixed threshold)"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::StatisticDetectors),
            real("zv_log_threshold", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Fixed threshold"),
                 &P::zv_log_threshold, -5.0, 15.0, "log10",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Fixed threshold on the statistic (log10), when not adaptive"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::FixedThreshold),
            real("zv_adapt_window_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Adaptive window"),
                 &P::zv_adapt_window_s, 0.1, 10.0, "s",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Adaptive: window of the running minimum (about one gait cycle)"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::AdaptiveThreshold),
            real("zv_adapt_offset_dec", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Offset above the minimum"),
                 &P::zv_adapt_offset_dec, 0.0, 5.0, "decades",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Adaptive: threshold above the running minimum"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::AdaptiveThreshold),
            real("zv_adapt_fraction", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Fraction towards the maximum"),
                 &P::zv_adapt_fraction, 0.0, 1.0, "x",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Adaptive: threshold this fraction of the way from the "
                                                                "running minimum to the maximum"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::AdaptiveThreshold),
            real("zv_log_always", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Always at rest below"),
                 &P::zv_log_always, -5.0, 15.0, "log10",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Adaptive: below this the foot is always at rest"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::AdaptiveThreshold),
            real("zv_log_never", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Never at rest above"),
                 &P::zv_log_never, -5.0, 15.0, "log10",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Adaptive: above this the foot is never at rest"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::AdaptiveThreshold),
            real("zv_min_stance_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Shortest stance"),
                 &P::zv_min_stance_s, 0.0, 2.0, "s",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Shorter stance runs are dropped"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::StatisticDetectors),
            real("acc_min_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C1 lower bound on |a|"),
                 &P::acc_min_mps2, 0.0, 50.0, "m/s^2",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "C1: lower bound on |a|"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::PaperDetector),
            real("acc_max_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C1 upper bound on |a|"),
                 &P::acc_max_mps2, 0.0, 200.0, "m/s^2",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "C1: upper bound on |a|"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::PaperDetector),
            real("acc_std_max_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C2 bound on the std of |a|"),
                 &P::acc_std_max_mps2, 0.0, 20.0, "m/s^2",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "C2: std of |a| over the window must be below"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::PaperDetector),
            real("window_half_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C2 half-window"), &P::window_half_s,
                 0.0, 2.0, "s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C2: half-window of the centred std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::PaperDetector),
            real("gyr_max_radps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C3 bound on |ω|"), &P::gyr_max_radps,
                 0.0, 20.0, "rad/s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C3: upper bound on |w|"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::PaperDetector),
            real("median_window_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Median filter length"),
                 &P::median_window_s, 0.0, 2.0, "s",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Median filter length applied to C"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), FieldScope::PaperDetector),
            choice("filter_states", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Filter states"), &P::filter_states,
                   {"15", "9"},
                   {QT_TRANSLATE_NOOP("footpath::ParameterFields", "15 states (with biases)"),
                    QT_TRANSLATE_NOOP("footpath::ParameterFields", "9 states (no bias states)")},
                   QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                     "Error-state filter size: 15 estimates the sensor biases, 9 holds them at zero"),
                   QT_TRANSLATE_NOOP("footpath::ParameterFields", "Filter")),
            choice("estimator", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Estimator"), &P::estimator,
                   {"ekf", "feliz", "rts"},
                   {QT_TRANSLATE_NOOP("footpath::ParameterFields", "Kalman filter"),
                    QT_TRANSLATE_NOOP("footpath::ParameterFields", "Feliz de-drift (no filter)"),
                    QT_TRANSLATE_NOOP("footpath::ParameterFields", "Kalman filter + RTS smoother")},
                   QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                     "Kalman filter with the measurements below, Feliz 2009's per-stride velocity "
                                     "de-drift, or the filter followed by a Rauch-Tung-Striebel smoother over the "
                                     "whole recording (offline; live input runs the filter)"),
                   QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
            flag("use_zupt", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Zero-velocity update (ZUPT)"),
                 &P::use_zupt, QT_TRANSLATE_NOOP("footpath::ParameterFields", "Zero-velocity update during stance"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
            flag("use_zaru", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Zero angular rate update (ZARU)"),
                 &P::use_zaru, QT_TRANSLATE_NOOP("footpath::ParameterFields", "Zero angular rate update during stance"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements"), FieldScope::Zaru),
            flag("use_hdr", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Heuristic drift reduction (HDR)"),
                 &P::use_hdr,
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Heuristic drift reduction: heading held on straight walks"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
            flag("use_iper", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Position error reduction (IPER)"),
                 &P::use_iper,
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Position error reduction: walks along the building's axes, level floor ("
                                   "assumes a rectilinear building)"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
            flag("use_zuna", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Zero navigation acceleration (ZUNA)"),
                 &P::use_zuna,
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Zero navigation acceleration at mid-stance"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
            flag("use_baro", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometric height"), &P::use_baro,
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometric height at each stance (Zheng et al. 2016)"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
            flag("use_mag_heading", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetometer heading"),
                 &P::use_mag_heading,
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Magnetometer heading during stance, skipped near steel"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
            real("hdr_lag_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR heading lag"), &P::hdr_lag_s, 0.05,
                 10.0, "s",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR: heading compared with the heading this long ago"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR"), FieldScope::Hdr),
            real("hdr_threshold_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR turn threshold"),
                 &P::hdr_threshold_rad, 0.0, 1.0, "rad",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "HDR: a smaller heading change is drift, a larger one a turn"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR"), FieldScope::Hdr),
            real("r_hdr_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR measurement std"), &P::r_hdr_rad,
                 1e-6, 1.0, "rad",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR: R of the heading measurement, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "HDR"), FieldScope::Hdr),
            flag("iper_axis_auto", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Building axis from the walk"),
                 &P::iper_axis_auto,
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "IPER: building axis from the walk's dominant directions"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER"), FieldScope::Iper),
            real("iper_axis_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Building axis angle"),
                 &P::iper_axis_rad, -M_PI, M_PI, "rad",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER: angle of the building's main axis from x"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER"), FieldScope::IperFixedAxis),
            real("iper_threshold_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Along-axis tolerance"),
                 &P::iper_threshold_rad, 0.0, 0.8, "rad",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "IPER: walking within this of an axis counts as along it"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER"), FieldScope::Iper),
            real("iper_window_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER window"), &P::iper_window_s, 0.2,
                 30.0, "s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER: displacement window"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER"), FieldScope::Iper),
            real("r_iper_m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER cross-axis std"), &P::r_iper_m, 1e-6,
                 10.0, "m",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER: R of the cross-axis displacement, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER"), FieldScope::Iper),
            real("r_iper_height_m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER level-floor height std"),
                 &P::r_iper_height_m, 1e-6, 10.0, "m",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER: R of the level-floor height, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "IPER"), FieldScope::Iper),
            real("zuna_reference_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA reference period"),
                 &P::zuna_reference_s, 0.1, 60.0, "s",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA: static start averaged for the reference"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA"), FieldScope::Zuna),
            real("zuna_min_stance_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA shortest stance"),
                 &P::zuna_min_stance_s, 0.0, 2.0, "s",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA: mid-stance needs a stance run this long"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA"), FieldScope::Zuna),
            real("zuna_margin_dec", QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA margin below the threshold"),
                 &P::zuna_margin_dec, 0.0, 5.0, "decades",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "ZUNA: mid-stance statistic this far below the threshold"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA"), FieldScope::Zuna),
            real("r_zuna_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA measurement std"), &P::r_zuna_mps2,
                 1e-6, 10.0, "m/s^2",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA: R of the acceleration, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "ZUNA"), FieldScope::Zuna),
            choice("baro_model", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Pressure to height"), &P::baro_model,
                   {"formula", "linear"},
                   {QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometric formula"),
                    QT_TRANSLATE_NOOP("footpath::ParameterFields", "Linear constant (Zheng et al. 2016)")},
                   QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer: pressure difference to height"),
                   QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer"), FieldScope::Barometer),
            real("baro_linear_m_per_pa", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Linear constant N"),
                 &P::baro_linear_m_per_pa, 0.0, 1.0, "m/Pa",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer: linear constant N"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer"), FieldScope::LinearBarometer),
            real("r_baro_m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer height std"), &P::r_baro_m, 1e-6,
                 100.0, "m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer: R of the height, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer"), FieldScope::Barometer),
            real("motion_level_max_m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Level walking height change"),
                 &P::motion_level_max_m, 0.0, 5.0, "m",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Motion class: smaller height change per step is level walking"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer")),
            real("motion_elevator_var_pa2",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Elevator pressure variance"),
                 &P::motion_elevator_var_pa2, 0.0, 1e6, "Pa^2",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Motion class: pressure variance between steps above this is an elevator"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer")),
            real("r_mag_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetometer heading std"), &P::r_mag_rad,
                 1e-6, 3.0, "rad",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetometer: R of the heading, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetometer"), FieldScope::MagHeading),
            real("mag_norm_tolerance", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Field strength tolerance"),
                 &P::mag_norm_tolerance, 0.0, 1.0, "x",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Magnetometer: |m| within this fraction of its value at alignment"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetometer"), FieldScope::MagHeading),
            real("mag_dip_tolerance_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Dip angle tolerance"),
                 &P::mag_dip_tolerance_rad, 0.0, 1.6, "rad",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Magnetometer: dip within this of its value at alignment"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetometer"), FieldScope::MagHeading),
            real("q_att_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q attitude"), &P::q_att_rad, 0.0, 1.0,
                 "rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q attitude, std per 10 ms"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Process noise")),
            real("q_gyro_bias_radps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q gyroscope bias"),
                 &P::q_gyro_bias_radps, 0.0, 1.0, "rad/s",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q gyro bias, std per 10 ms"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Process noise"), FieldScope::BiasStates),
            real("q_pos_m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q position"), &P::q_pos_m, 0.0, 1.0, "m",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q position, std per 10 ms"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Process noise")),
            real("q_vel_mps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q velocity"), &P::q_vel_mps, 0.0, 1.0,
                 "m/s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q velocity, std per 10 ms"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Process noise")),
            real("q_acc_bias_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q accelerometer bias"),
                 &P::q_acc_bias_mps2, 0.0, 1.0, "m/s^2",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q accelerometer bias, std per 10 ms"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Process noise"), FieldScope::BiasStates),
            real("r_zupt_mps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "R zero velocity"), &P::r_zupt_mps, 1e-6,
                 10.0, "m/s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "R ZUPT, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurement noise")),
            real("r_zaru_radps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "R zero angular rate"),
                 &P::r_zaru_radps, 1e-6, 10.0, "rad/s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "R ZARU, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurement noise"), FieldScope::Zaru),
            real("p0_att_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 attitude"), &P::p0_att_rad, 0.0, 10.0,
                 "rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 attitude, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Initial covariance")),
            real("p0_gyro_bias_radps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 gyroscope bias"),
                 &P::p0_gyro_bias_radps, 0.0, 10.0, "rad/s",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 gyro bias, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Initial covariance"), FieldScope::BiasStates),
            real("p0_pos_m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 position"), &P::p0_pos_m, 0.0, 100.0,
                 "m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 position, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Initial covariance")),
            real("p0_vel_mps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 velocity"), &P::p0_vel_mps, 0.0,
                 100.0, "m/s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 velocity, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Initial covariance")),
            real("p0_acc_bias_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 accelerometer bias"),
                 &P::p0_acc_bias_mps2, 0.0, 100.0, "m/s^2",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 accelerometer bias, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Initial covariance"), FieldScope::BiasStates),
    };
}
std::string formatNumber(double value)
{
    std::ostringstream out;
    out << value;
    return out.str();
}

bool parseFlag(const std::string& text, bool& value)
{
    std::string lower = text;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return std::tolower(ch); });
    if (lower == "1" || lower == "true" || lower == "on" || lower == "yes") {
        value = true;
        return true;
    }
    if (lower == "0" || lower == "false" || lower == "off" || lower == "no") {
        value = false;
        return true;
    }
    return false;
}

bool parseReal(const std::string& text, double& value)
{
    if (text.empty())
        return false;
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(value);
}

}  // namespace

Parameters guo2015Parameters()
{
    Parameters params;
    params.detector = static_cast<int>(DetectorKind::PaperC1C2C3);
    params.filter_states = static_cast<int>(FilterStates::Fifteen);
    params.use_zaru = true;
    params.q_att_rad = 1e-4;
    params.q_vel_mps = 1e-4;
    params.r_zupt_mps = 0.01;
    params.estimator = static_cast<int>(EstimatorKind::Ekf);  // the paper filters; it has no smoother
    return params;
}

const std::vector<ParameterField>& parameterFields()
{
    static const std::vector<ParameterField> fields = makeFields();
    return fields;
}

std::string displayUnit(const ParameterField& field)
{
    std::string unit = field.unit;
    if (unit == "x")  // a fraction or factor: nothing to write
        return {};
    for (std::size_t at = unit.find("^2"); at != std::string::npos; at = unit.find("^2"))
        unit.replace(at, 2, "\u00b2");
    return unit;
}

std::string labelWithUnit(const ParameterField& field)
{
    const std::string unit = displayUnit(field);
    return unit.empty() ? std::string(field.label) : std::string(field.label) + " (" + unit + ")";
}

const ParameterField* findParameterField(const std::string& name)
{
    for (const ParameterField& field : parameterFields())
        if (name == field.name)
            return &field;
    return nullptr;
}

double parameterValue(const Parameters& params, const ParameterField& field)
{
    switch (field.kind) {
    case K::Real:
        return params.*field.real;
    case K::Flag:
        return params.*field.flag ? 1.0 : 0.0;
    case K::Choice:
        return static_cast<double>(params.*field.choice);
    }
    return 0.0;
}

std::string choiceName(const Parameters& params, const ParameterField& field)
{
    if (field.kind != K::Choice)
        return {};
    const int index = params.*field.choice;
    return index >= 0 && index < static_cast<int>(field.choiceNames.size()) ? field.choiceNames[index] : "?";
}

namespace {

std::string setChoice(Parameters& params, const ParameterField& field, const std::string& text)
{
    std::string known;
    for (std::size_t i = 0; i < field.choiceNames.size(); ++i) {
        if (text == field.choiceNames[i]) {
            params.*field.choice = static_cast<int>(i);
            return {};
        }
        known += (i > 0 ? ", " : "") + std::string(field.choiceNames[i]);
    }
    return "parameter '" + std::string(field.name) + "' expects one of " + known + ", got '" + text + "'";
}

}  // namespace

namespace {

bool statisticReadsAccelerometer(DetectorKind kind)
{
    return kind != DetectorKind::Ared;
}

bool statisticReadsGyroscope(DetectorKind kind)
{
    return kind == DetectorKind::Shoe || kind == DetectorKind::Ared;
}

}  // namespace

FieldScope unmetScope(const ParameterField& field, const Parameters& params)
{
    using S = FieldScope;
    const DetectorKind detector = params.detectorKind();
    const bool paper = detector == DetectorKind::PaperC1C2C3;
    const bool fifteen = params.filterStates() == FilterStates::Fifteen;
    switch (field.scope) {
    case S::Always:
        return S::Always;
    case S::PaperDetector:
        return paper ? S::Always : S::PaperDetector;
    case S::StatisticDetectors:
    case S::DetectorAccelerometer:
    case S::DetectorGyroscope:
    case S::FixedThreshold:
    case S::AdaptiveThreshold:
        break;
    case S::BiasStates:
    case S::Zaru:
        return fifteen ? S::Always : field.scope;
    case S::Hdr:
        return params.use_hdr ? S::Always : S::Hdr;
    case S::Iper:
        return params.use_iper ? S::Always : S::Iper;
    case S::IperFixedAxis:
        return !params.use_iper ? S::Iper : params.iper_axis_auto ? S::IperFixedAxis : S::Always;
    case S::Zuna:
        return params.use_zuna ? S::Always : S::Zuna;
    case S::Barometer:
        return params.use_baro ? S::Always : S::Barometer;
    case S::LinearBarometer:
        return !params.use_baro ? S::Barometer
               : params.barometerModel() == BarometerModel::Linear ? S::Always : S::LinearBarometer;
    case S::MagHeading:
        return params.use_mag_heading ? S::Always : S::MagHeading;
    }
    if (paper)
        return S::StatisticDetectors;
    const bool met = field.scope == S::StatisticDetectors
                     || (field.scope == S::DetectorAccelerometer && statisticReadsAccelerometer(detector))
                     || (field.scope == S::DetectorGyroscope && statisticReadsGyroscope(detector))
                     || (field.scope == S::FixedThreshold && !params.zv_adaptive)
                     || (field.scope == S::AdaptiveThreshold && params.zv_adaptive);
    return met ? S::Always : field.scope;
}

bool operator==(const Parameters& a, const Parameters& b)
{
    for (const ParameterField& field : parameterFields())
        if (parameterValue(a, field) != parameterValue(b, field))
            return false;
    return true;
}

std::string setParameter(Parameters& params, const std::string& name, const std::string& text)
{
    const ParameterField* field = findParameterField(name);
    if (!field)
        return "unknown parameter '" + name + "'";
    if (field->kind == K::Choice)
        return setChoice(params, *field, text);
    if (field->kind == K::Flag) {
        if (!parseFlag(text, params.*field->flag))
            return "parameter '" + name + "' expects true/false, got '" + text + "'";
        return {};
    }
    double value = 0.0;
    if (!parseReal(text, value))
        return "parameter '" + name + "' expects a number, got '" + text + "'";
    params.*field->real = value;
    return {};
}

std::vector<std::string> Parameters::validate() const
{
    std::vector<std::string> problems;
    for (const ParameterField& field : parameterFields()) {
        if (field.kind == K::Choice) {
            const int index = this->*field.choice;
            if (index < 0 || index >= static_cast<int>(field.choiceNames.size()))
                problems.push_back(std::string(field.name) + " (" + std::to_string(index) + ") is not a known choice");
            continue;
        }
        if (field.kind != K::Real)
            continue;
        const double value = this->*field.real;
        if (!std::isfinite(value) || value < field.minimum || value > field.maximum)
            problems.push_back(std::string(field.name) + " (" + formatNumber(value) + ") must be between "
                               + formatNumber(field.minimum) + " and " + formatNumber(field.maximum)
                               + (displayUnit(field).empty() ? "" : " " + displayUnit(field)));  // m/s², as the window writes it
    }
    if (acc_min_mps2 >= acc_max_mps2)
        problems.push_back("acc_min_mps2 (" + formatNumber(acc_min_mps2) + ") must be below acc_max_mps2 ("
                           + formatNumber(acc_max_mps2) + ")");
    if (zv_log_always >= zv_log_never)
        problems.push_back("zv_log_always (" + formatNumber(zv_log_always) + ") must be below zv_log_never ("
                           + formatNumber(zv_log_never) + ")");
    return problems;
}

}  // namespace footpath
