#include "nav/sources/BarometricHeight.h"

#include "methods/SourceMethodSupport.h"
#include "nav/ErrorStateEkf.h"
#include "nav/MotionClasses.h"

#include <QtGlobal>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace footpath {

namespace {

/// Neighbours on each side whose median a sample is compared with.
constexpr std::size_t kSpikeHalfWindow = 5;
/// About six standard deviations of the ecg-xmu barometer at rest (1.5-2.5 Pa), 1 m of height;
/// an elevator at 1 m/s changes the pressure by 0.6 Pa across the window.
constexpr double kSpikeThreshold_pa = 12.0;
/// A stance this long may hold an elevator ride (the shortest ride, one floor, takes several
/// seconds); shorter stances are too noisy to compare their parts.
constexpr double kMinRideStance_s = 2.0;
/// The first and last part of a long stance: 50 samples at 100 Hz average the noise to ~0.3 Pa.
constexpr double kStancePart_s = 0.5;
/// The measurement noise of a stance that spans a ride, as a fraction of r_baro_m.
constexpr double kRideResetNoiseFactor = 0.01;

/// The samples [first, last) that sample i is compared with: itself and kSpikeHalfWindow
/// neighbours on each side.
struct Neighbourhood {
    std::size_t first = 0, last = 0;
};

Neighbourhood neighbourhoodOf(const std::vector<double>& pressures_pa, std::size_t i)
{
    return {i >= kSpikeHalfWindow ? i - kSpikeHalfWindow : 0, std::min(pressures_pa.size(), i + kSpikeHalfWindow + 1)};
}

/// The median of the neighbourhood: its (size / 2)-th smallest value, counted from 0.
double neighbourMedian(const std::vector<double>& pressures_pa, std::size_t i)
{
    const Neighbourhood around = neighbourhoodOf(pressures_pa, i);
    std::array<double, 2 * kSpikeHalfWindow + 1> values{};
    const auto end = std::copy(pressures_pa.begin() + static_cast<std::ptrdiff_t>(around.first),
                               pressures_pa.begin() + static_cast<std::ptrdiff_t>(around.last), values.begin());
    const auto middle = values.begin() + (end - values.begin()) / 2;
    std::nth_element(values.begin(), middle, end);
    return *middle;
}

/// True if some pressure is NaN or infinite: a neighbourhood with a NaN has no defined order, and
/// an infinite difference of infinities is NaN.
bool hasNonFinite(const std::vector<double>& pressures_pa)
{
    return !std::all_of(pressures_pa.begin(), pressures_pa.end(), [](double p) { return std::isfinite(p); });
}

/// Whether sample i lies more than kSpikeThreshold_pa from its neighbourhood's median m, that is
/// |p_i - m| > threshold, without sorting for m. p_i - w does not grow as w does, so the
/// neighbours with p_i - w > threshold are the smallest ones, and m (the middle-th smallest) is
/// among them when there are more than `middle`; likewise those with p_i - w < -threshold are the
/// largest, and hold m when there are at least size - middle. Once more than `middle` neighbours
/// are neither, neither count can get there. Each difference is the one the median's test
/// computes, rounded alike: the same answer to the last bit. With a NaN or an infinity among the
/// pressures (`nonFinite`) the median is taken as before.
bool isSpike(const std::vector<double>& pressures_pa, std::size_t i, bool nonFinite)
{
    if (nonFinite)
        return std::abs(pressures_pa[i] - neighbourMedian(pressures_pa, i)) > kSpikeThreshold_pa;
    const Neighbourhood around = neighbourhoodOf(pressures_pa, i);
    const std::size_t size = around.last - around.first, middle = size / 2;
    std::size_t farBelow = 0, farAbove = 0, near = 0;
    for (std::size_t j = around.first; j < around.last; ++j) {
        const double difference = pressures_pa[i] - pressures_pa[j];
        if (difference > kSpikeThreshold_pa)
            ++farBelow;
        else if (difference < -kSpikeThreshold_pa)
            ++farAbove;
        else if (++near > middle)
            return false;
    }
    return farBelow > middle || farAbove >= size - middle;
}

/// Mean of the samples whose time lies in [from_s, to_s].
double meanBetween(const std::vector<double>& times_s, const std::vector<double>& pressures_pa, double from_s,
                   double to_s)
{
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < times_s.size(); ++i) {
        if (times_s[i] >= from_s && times_s[i] <= to_s) {
            sum += pressures_pa[i];
            ++count;
        }
    }
    return count == 0 ? std::nan("") : sum / static_cast<double>(count);
}

}  // namespace

std::vector<double> despikedPressure(const std::vector<double>& pressures_pa)
{
    std::vector<double> clean = pressures_pa;
    const bool nonFinite = hasNonFinite(pressures_pa);
    for (std::size_t i = 0; i < pressures_pa.size(); ++i)
        if (isSpike(pressures_pa, i, nonFinite))
            clean[i] = neighbourMedian(pressures_pa, i);
    return clean;
}

StancePressure readStancePressure(const std::vector<double>& times_s, const std::vector<double>& pressures_pa)
{
    StancePressure result;
    if (pressures_pa.empty() || times_s.size() != pressures_pa.size()) {
        result.mean_pa = result.first_pa = result.last_pa = std::nan("");
        return result;
    }
    std::vector<double> kept_s, kept_pa;
    kept_s.reserve(times_s.size());
    kept_pa.reserve(pressures_pa.size());
    const bool nonFinite = hasNonFinite(pressures_pa);
    for (std::size_t i = 0; i < pressures_pa.size(); ++i) {
        if (!isSpike(pressures_pa, i, nonFinite)) {
            kept_s.push_back(times_s[i]);
            kept_pa.push_back(pressures_pa[i]);
        }
    }
    if (kept_pa.empty()) {  // all spikes cannot happen with a median, but stay defined
        kept_s = times_s;
        kept_pa = pressures_pa;
    }
    result.mean_pa = meanBetween(kept_s, kept_pa, kept_s.front(), kept_s.back());
    result.first_pa = result.last_pa = result.mean_pa;
    if (kept_s.back() - kept_s.front() >= kMinRideStance_s) {
        result.spansHeightChange = true;
        result.first_pa = meanBetween(kept_s, kept_pa, kept_s.front(), kept_s.front() + kStancePart_s);
        result.last_pa = meanBetween(kept_s, kept_pa, kept_s.back() - kStancePart_s, kept_s.back());
    }
    return result;
}

void BarometricHeightSource::apply(ErrorStateEkf& ekf, const SourceContext& context)
{
    const ImuSample& sample = context.sample;
    if (!sawSample_) {
        sawSample_ = true;
        firstTime_s_ = sample.time_s;
        hasPressure_ = sample.hasPressure();
    }
    if (!hasPressure_)
        return;
    if (context.flags.stance) {
        if (sample.hasPressure()) {  // a missing reading inside a recording with pressure: skip it
            runTimes_s_.push_back(sample.time_s);
            runPressures_pa_.push_back(sample.pressure_pa);
        }
        return;
    }
    if (!runPressures_pa_.empty())
        stanceEnded(ekf);
    runTimes_s_.clear();
    runPressures_pa_.clear();
}

void BarometricHeightSource::stanceEnded(ErrorStateEkf& ekf)
{
    const StancePressure pressure = readStancePressure(runTimes_s_, runPressures_pa_);
    if (!haveReference_) {
        haveReference_ = true;
        referencePressure_pa_ = pressure.mean_pa;
        referenceZ_m_ = ekf.state().position_m.z();
        return;
    }
    const double meanHeight_m = barometricHeight(pressure.mean_pa, referencePressure_pa_, params_);
    const double rideHeight_m = barometricHeight(pressure.last_pa, pressure.first_pa, params_);
    if (std::abs(rideHeight_m) <= kMinStanceRide_m) {
        updateHeight(ekf, referenceZ_m_ + meanHeight_m, params_.r_baro_m);
        return;
    }
    // A ride: the inertial height holds no information about it, so the barometer resets it (the
    // gain is R against the filter's variance; a hundredth of the usual R makes it nearly 1).
    updateHeight(ekf, referenceZ_m_ + barometricHeight(pressure.last_pa, referencePressure_pa_, params_),
                 kRideResetNoiseFactor * params_.r_baro_m);
}

void BarometricHeightSource::updateHeight(ErrorStateEkf& ekf, double measuredZ_m, double noiseStd_m)
{
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(1, ErrorStateEkf::kStates);
    h(0, ErrorStateEkf::kPos + 2) = 1.0;  // dr_z = estimate - truth
    ekf.updateRows(h, Eigen::VectorXd::Constant(1, ekf.state().position_m.z() - measuredZ_m),
                   Eigen::VectorXd::Constant(1, noiseStd_m * noiseStd_m));
}

void BarometricHeightSource::finish(double endTime_s, std::vector<MethodNote>& notes)
{
    if (!sawSample_ || hasPressure_)
        return;
    notes.push_back(MethodNote{"baro", firstTime_s_, endTime_s,
                               "not applied: the recording has no pressure readings, so there is no barometric height"});
}


// ---- registry entry (core/methods/SourceMethods.cpp lists it) ----------------------------

namespace {

const FieldCondition baroOn{"baro", methods::switchIsOn<&Parameters::use_baro>,
    QT_TRANSLATE_NOOP("footpath::ParameterPanel", "Not used: the barometer is off (use_baro).")};
const FieldCondition linearBarometer{
    "linear_barometer", [](const Parameters& p) { return p.barometerModel() == BarometerModel::Linear; },
    QT_TRANSLATE_NOOP("footpath::ParameterPanel", "Not used: the barometric formula is chosen, not the linear constant."),
    &baroOn};

}  // namespace

SourceMethod barometricHeightMethod()
{
    const auto fields = [] {
        using P = Parameters;
        return std::vector<ParameterField>{
            flagField("use_baro", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometric height"), &P::use_baro,
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometric height at each stance (Zheng et al. 2016)"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
            choiceField("baro_model", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Pressure to height"), &P::baro_model,
                   {"formula", "linear"},
                   {QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometric formula"),
                    QT_TRANSLATE_NOOP("footpath::ParameterFields", "Linear constant (Zheng et al. 2016)")},
                   QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer: pressure difference to height"),
                   QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer"), &baroOn),
            realField("baro_linear_m_per_pa", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Linear constant N"),
                 &P::baro_linear_m_per_pa, 0.0, 1.0, "m/Pa",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer: linear constant N"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer"), &linearBarometer),
            realField("r_baro_m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer height std"), &P::r_baro_m, 1e-6,
                 100.0, "m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer: R of the height, std"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer"), &baroOn),
            realField("motion_level_max_m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Level walking height change"),
                 &P::motion_level_max_m, 0.0, 5.0, "m",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Motion class: smaller height change per step is level walking"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer")),
            realField("motion_elevator_var_pa2",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Elevator pressure variance"),
                 &P::motion_elevator_var_pa2, 0.0, 1e6, "Pa^2",
                 QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                   "Motion class: pressure variance between steps above this is an elevator"),
                 QT_TRANSLATE_NOOP("footpath::ParameterFields", "Barometer")),
        };
    };
    return {"baro", "barometer", "use_baro", methods::switchIsOn<&Parameters::use_baro>, methods::setSwitch<&Parameters::use_baro>,
            methods::makeWhenOn<BarometricHeightSource, &Parameters::use_baro>, fields, 60};
}

}  // namespace footpath
