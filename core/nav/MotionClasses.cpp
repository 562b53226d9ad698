#include "nav/MotionClasses.h"

#include "nav/sources/BarometricHeight.h"

#include <algorithm>
#include <cmath>

namespace footpath {

const char* motionClassName(MotionClass motion)
{
    switch (motion) {
    case MotionClass::Unknown:
        return "unknown";
    case MotionClass::Level:
        return "level";
    case MotionClass::StairsUp:
        return "stairs_up";
    case MotionClass::StairsDown:
        return "stairs_down";
    case MotionClass::ElevatorUp:
        return "elevator_up";
    case MotionClass::ElevatorDown:
        return "elevator_down";
    }
    return "unknown";
}

double barometricHeight(double pressure_pa, double reference_pa, const Parameters& params)
{
    if (params.barometerModel() == BarometerModel::Linear)
        return params.baro_linear_m_per_pa * (reference_pa - pressure_pa);
    // International barometric formula, relative to the reference pressure (ISA troposphere).
    return 44330.8 * (1.0 - std::pow(pressure_pa / reference_pa, 1.0 / 5.25588));
}

namespace {

/// A stance at least this long is a step of its own for the classes (walking: 0.3-0.5 s).
constexpr double kMinFullStance_s = 0.15;

/// A stance's samples as indices [first, last) into the recording.
struct SampleSpan {
    std::size_t first = 0;
    std::size_t last = 0;
};

/// What Zheng et al. 2016's rules read of one step.
struct StepMeasures {
    double height_m = 0.0;            ///< the stance's barometric height against the first stance
    double heightChange_m = 0.0;      ///< against the previous step's
    double rideHeight_m = 0.0;        ///< height change inside this stance (last part minus first)
    double windowVariance_pa2 = 0.0;  ///< pressure variance from the previous stance's start to this one's end
};

SampleSpan stanceSamples(const std::vector<ImuSample>& samples, const Step& step)
{
    const auto beforeTime = [](const ImuSample& sample, double time_s) { return sample.time_s < time_s; };
    const auto afterTime = [](double time_s, const ImuSample& sample) { return time_s < sample.time_s; };
    SampleSpan span;
    span.first = static_cast<std::size_t>(
        std::lower_bound(samples.begin(), samples.end(), step.stanceStart_s, beforeTime) - samples.begin());
    span.last = static_cast<std::size_t>(
        std::upper_bound(samples.begin(), samples.end(), step.stanceEnd_s, afterTime) - samples.begin());
    return span;
}

StancePressure pressureOver(const std::vector<ImuSample>& samples, const SampleSpan& span)
{
    std::vector<double> times_s, pressures_pa;
    if (span.last > span.first) {  // an empty span (a step ending before it starts) reserves nothing
        times_s.reserve(span.last - span.first);
        pressures_pa.reserve(span.last - span.first);
    }
    for (std::size_t k = span.first; k < span.last; ++k) {
        if (samples[k].hasPressure()) {
            times_s.push_back(samples[k].time_s);
            pressures_pa.push_back(samples[k].pressure_pa);
        }
    }
    return readStancePressure(times_s, pressures_pa);
}

double variance(const std::vector<double>& values, std::size_t first, std::size_t last)
{
    double sum = 0.0, sumSquares = 0.0;
    std::size_t count = 0;
    for (std::size_t k = first; k < last; ++k) {
        if (std::isnan(values[k]))
            continue;
        sum += values[k];
        sumSquares += values[k] * values[k];
        ++count;
    }
    if (count < 2)
        return 0.0;
    const double mean = sum / static_cast<double>(count);
    return std::max(0.0, sumSquares / static_cast<double>(count) - mean * mean);
}

/// Zheng et al. 2016's rule, with one addition: the height changing inside one stance is an elevator
/// ride whatever the step-to-step change says. A rider stands, so the ride usually falls inside
/// one long stance whose mean height lies somewhere in the middle of the ride; the paper's
/// step-to-step rule then sees the ride split over two steps, and when the rider shuffles a foot
/// mid-ride over more. Stairs never change the height while the foot rests.
MotionClass classifyStep(const StepMeasures& step, const Parameters& params)
{
    if (std::abs(step.rideHeight_m) > kMinStanceRide_m)
        return step.rideHeight_m > 0.0 ? MotionClass::ElevatorUp : MotionClass::ElevatorDown;
    if (std::abs(step.heightChange_m) < params.motion_level_max_m)
        return MotionClass::Level;
    const bool up = step.heightChange_m > 0.0;
    if (step.windowVariance_pa2 > params.motion_elevator_var_pa2)
        return up ? MotionClass::ElevatorUp : MotionClass::ElevatorDown;
    return up ? MotionClass::StairsUp : MotionClass::StairsDown;
}

bool isElevator(MotionClass motion)
{
    return motion == MotionClass::ElevatorUp || motion == MotionClass::ElevatorDown;
}

/// A rider who shifts a foot mid-ride splits the ride over several stances, and a short window
/// between two of them has little pressure variance: a step that continues an elevator step in
/// the same direction, still changing height, is still the ride.
MotionClass continueRide(MotionClass motion, MotionClass previous)
{
    const bool stairs = motion == MotionClass::StairsUp || motion == MotionClass::StairsDown;
    if (!stairs || !isElevator(previous))
        return motion;
    const bool sameDirection = (motion == MotionClass::StairsUp) == (previous == MotionClass::ElevatorUp);
    return sameDirection ? previous : motion;
}

void countMotion(Result& result, const std::vector<StepMeasures>& measures, const std::vector<bool>& counted)
{
    Summary& summary = result.summary;
    MotionClass previous = MotionClass::Unknown;
    for (std::size_t k = 0; k < result.steps.size(); ++k) {
        if (!counted[k])
            continue;
        const MotionClass motion = result.steps[k].motion;
        if (motion == MotionClass::StairsUp) {
            ++summary.stairStepsUp;
            summary.stairsClimb_m += measures[k].heightChange_m;
        } else if (motion == MotionClass::StairsDown) {
            ++summary.stairStepsDown;
            summary.stairsDescent_m -= measures[k].heightChange_m;
        } else if (isElevator(motion) && motion != previous) {
            ++summary.elevatorRides;  // consecutive elevator steps in one direction are one ride
        }
        previous = motion;
    }
}

}  // namespace

void classifyMotion(const Recording& recording, const Parameters& params, Result& result)
{
    Summary& summary = result.summary;
    summary.stairStepsUp = summary.stairStepsDown = summary.elevatorRides = 0;
    summary.stairsClimb_m = summary.stairsDescent_m = 0.0;
    for (Step& step : result.steps) {
        step.motion = MotionClass::Unknown;
        step.baroHeight_m = std::nan("");
    }
    if (!recording.hasPressure() || result.steps.empty())
        return;

    const std::vector<ImuSample>& samples = recording.samples;
    std::vector<double> rawPressure_pa(samples.size());
    std::transform(samples.begin(), samples.end(), rawPressure_pa.begin(),
                   [](const ImuSample& sample) { return sample.pressure_pa; });
    const std::vector<double> pressure_pa = despikedPressure(rawPressure_pa);

    // Short stances (the detector's fragments between the real ones) average too few samples and
    // catch the pressure swing of a moving foot: they get a height but are compared with nothing;
    // they share the class of the last full stance and are not counted as steps of their own.
    std::vector<StepMeasures> measures(result.steps.size());
    std::vector<bool> full(result.steps.size(), false);
    SampleSpan previousSpan;
    double reference_pa = 0.0;
    std::size_t previousFull = 0;
    bool haveFull = false;
    MotionClass previousMotion = MotionClass::Level;
    for (std::size_t k = 0; k < result.steps.size(); ++k) {
        const SampleSpan span = stanceSamples(samples, result.steps[k]);
        const StancePressure pressure = pressureOver(samples, span);
        if (k == 0)
            reference_pa = pressure.mean_pa;
        StepMeasures& step = measures[k];
        step.height_m = barometricHeight(pressure.mean_pa, reference_pa, params);
        step.rideHeight_m = barometricHeight(pressure.last_pa, pressure.first_pa, params);
        result.steps[k].baroHeight_m = step.height_m;
        full[k] = result.steps[k].stanceEnd_s - result.steps[k].stanceStart_s >= kMinFullStance_s;
        if (!full[k]) {
            result.steps[k].motion = previousMotion;
            continue;
        }
        if (haveFull) {
            step.heightChange_m = step.height_m - measures[previousFull].height_m;
            step.windowVariance_pa2 = variance(pressure_pa, previousSpan.first, span.last);
        }
        result.steps[k].motion = continueRide(classifyStep(step, params), previousMotion);
        previousMotion = result.steps[k].motion;
        previousFull = k;
        haveFull = true;
        previousSpan = span;
    }
    countMotion(result, measures, full);
}

}  // namespace footpath
