#include "nav/InputCheck.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace footpath {

bool hasFiniteInertialValues(const ImuSample& sample)
{
    return std::isfinite(sample.time_s) && sample.acc_mps2.allFinite() && sample.gyr_radps.allFinite();
}

std::string describeUnusableSamples(const std::vector<ImuSample>& samples)
{
    std::size_t badCount = 0;
    std::ostringstream first;
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const ImuSample& sample = samples[k];
        const bool backwards = k > 0 && sample.time_s < samples[k - 1].time_s;
        if (hasFiniteInertialValues(sample) && !backwards)
            continue;
        if (badCount++ > 0)
            continue;
        first << "sample " << k + 1;
        if (!std::isfinite(sample.time_s))
            first << " has no finite time (" << sample.time_s << ")";
        else if (backwards)
            first << " (t = " << sample.time_s << " s) goes back in time from " << samples[k - 1].time_s << " s";
        else
            first << " (t = " << sample.time_s << " s) has a non-finite "
                  << (sample.acc_mps2.allFinite() ? "gyroscope" : "accelerometer") << " value";
    }
    if (badCount == 0)
        return {};
    std::ostringstream out;
    out << first.str();
    if (badCount > 1)
        out << " (and " << badCount - 1 << " more such samples)";
    out << ": the recording is damaged there and cannot be estimated";
    return out.str();
}

namespace {

constexpr double kSaturationFloorAcc_mps2 = 2.0 * 9.81;
constexpr double kSaturationFloorGyr_radps = 3.0;
constexpr std::size_t kSaturatedSamplesToWarn = 3;

struct ClippedAxis {
    std::size_t count = 0;       ///< samples at the extreme value
    bool consecutive = false;    ///< two of them in a row
    std::size_t first = 0;
};

/// How many samples sit at the largest absolute value of one axis (signed extreme) and whether
/// any two of them are neighbours.
template <typename Value>
ClippedAxis clippedAt(const std::vector<ImuSample>& samples, const Value& value, double extreme)
{
    ClippedAxis clipped;
    bool previousAtExtreme = false;
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const bool atExtreme = value(samples[k]) == extreme;
        if (atExtreme && clipped.count++ == 0)
            clipped.first = k;
        clipped.consecutive = clipped.consecutive || (atExtreme && previousAtExtreme);
        previousAtExtreme = atExtreme;
    }
    return clipped;
}

/// value: the axis of a sample (a lambda, called directly on every import's every sample).
template <typename Value>
void checkAxis(const std::vector<ImuSample>& samples, const Value& value, const char* name, const char* unit,
               double floor, std::vector<std::string>& warnings)
{
    double lowest = 0.0;
    double highest = 0.0;
    for (const ImuSample& sample : samples) {
        const double v = value(sample);
        lowest = std::min(lowest, v);
        highest = std::max(highest, v);
    }
    for (const double extreme : {lowest, highest}) {
        if (!(std::abs(extreme) > floor))
            continue;
        const ClippedAxis clipped = clippedAt(samples, value, extreme);
        if (clipped.count < kSaturatedSamplesToWarn || !clipped.consecutive)
            continue;
        std::ostringstream text;
        text << "the " << name << " reads exactly " << extreme << " " << unit << " in " << clipped.count
             << " samples (first at t = " << samples[clipped.first].time_s
             << " s): the sensor was saturated there, so the motion was larger than recorded and the path"
                " is too short or bent";
        warnings.push_back(text.str());
    }
}

}  // namespace

std::vector<std::string> describeSaturation(const std::vector<ImuSample>& samples)
{
    std::vector<std::string> warnings;
    static const char* const kAxes[] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        checkAxis(samples, [axis](const ImuSample& s) { return s.acc_mps2[axis]; },
                  (std::string("accelerometer's ") + kAxes[axis] + " axis").c_str(), "m/s^2",
                  kSaturationFloorAcc_mps2, warnings);
        checkAxis(samples, [axis](const ImuSample& s) { return s.gyr_radps[axis]; },
                  (std::string("gyroscope's ") + kAxes[axis] + " axis").c_str(), "rad/s", kSaturationFloorGyr_radps,
                  warnings);
    }
    return warnings;
}

}  // namespace footpath
