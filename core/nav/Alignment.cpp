#include "nav/Alignment.h"

#include "detect/StanceFlagsAhead.h"

#include "nav/Attitude.h"
#include "nav/ErrorStateEkf.h"
#include "nav/Pipeline.h"

#include <algorithm>
#include <cmath>

namespace footpath {

namespace {

/// One past the last sample of the alignment period that starts at sample first: the samples at
/// most alignment_s after it, those averageStatic averages (and whose flags it reads).
std::size_t alignmentPeriodEnd(const std::vector<ImuSample>& samples, std::size_t first, double alignment_s)
{
    const double end_s = samples[first].time_s + alignment_s;
    std::size_t k = first;
    while (k < samples.size() && samples[k].time_s <= end_s)
        ++k;
    return k;
}

struct StaticMeans {
    Eigen::Vector3d acc = Eigen::Vector3d::Zero();
    Eigen::Vector3d mag = Eigen::Vector3d::Zero();
    std::size_t count = 0;
    std::size_t magCount = 0;
};

StaticMeans averageStatic(const std::vector<ImuSample>& samples, const std::vector<std::uint8_t>& stance,
                          std::size_t first, double alignment_s, bool requireStance)
{
    StaticMeans means;
    const std::size_t end = alignmentPeriodEnd(samples, first, alignment_s);
    for (std::size_t k = first; k < end; ++k) {
        if (requireStance && (k >= stance.size() || !stance[k]))
            continue;
        means.acc += samples[k].acc_mps2;
        ++means.count;
        if (samples[k].hasMag()) {
            means.mag += samples[k].mag;
            ++means.magCount;
        }
    }
    if (means.count > 0)
        means.acc /= static_cast<double>(means.count);
    if (means.magCount > 0)
        means.mag /= static_cast<double>(means.magCount);
    return means;
}

}  // namespace

std::size_t waitForAlignmentFlags(StanceFlagsAhead& ahead, const std::vector<ImuSample>& samples,
                                  const std::vector<std::uint8_t>& stance, double alignment_s)
{
    // alignmentStart, a flag at a time: the first stance sample, or 0 when there is none (every
    // flag read by then).
    std::size_t first = 0;
    while (first < samples.size()) {
        ahead.waitFor(first + 1);
        if (stance[first])
            break;
        ++first;
    }
    if (first == samples.size())
        return 0;
    ahead.waitFor(alignmentPeriodEnd(samples, first, alignment_s));
    return first;
}

std::size_t alignmentStart(const std::vector<std::uint8_t>& stance)
{
    if (stance.empty() || stance.front())
        return 0;
    const auto firstStance = std::find(stance.begin(), stance.end(), std::uint8_t(1));
    return firstStance == stance.end() ? 0 : static_cast<std::size_t>(firstStance - stance.begin());
}

void holdAtStart(const ErrorStateEkf& ekf, double time_s, Result& result)
{
    recordState(result, time_s, ekf.state());
    result.errorStd.push_back(ekf.covariance().diagonal().cwiseMax(0.0).cwiseSqrt().cast<float>());
}

double magneticHeading(const Eigen::Vector3d& magBody, double roll, double pitch, double declination_rad)
{
    // Rotate the body reading into the level frame (yaw 0): m_level = Ry(pitch) Rx(roll) m_b.
    const Eigen::Vector3d level = rotationFromRollPitchYaw(roll, pitch, 0.0) * magBody;
    // The yaw that turns the horizontal field onto +x (magnetic north); true north lies the
    // declination further west, i.e. counter-clockwise about z up is west in a North-West-Up frame.
    return -std::atan2(level.y(), level.x()) - declination_rad;
}

AlignmentResult alignInitialAttitude(const std::vector<ImuSample>& samples, const std::vector<std::uint8_t>& stance,
                                     const Parameters& params)
{
    AlignmentResult result;
    if (samples.empty())
        return result;
    const std::size_t first = std::min(alignmentStart(stance), samples.size() - 1);
    StaticMeans means = averageStatic(samples, stance, first, params.alignment_s, true);
    if (means.count == 0)
        means = averageStatic(samples, stance, first, params.alignment_s, false);
    const Eigen::Vector3d& f = means.acc;
    // Eq. 1-2 for C = Rz Ry Rx: at rest f_b = C^T [0 0 g] = g [-sin p, sin r cos p, cos r cos p].
    result.roll_rad = std::atan2(f.y(), f.z());
    result.pitch_rad = std::atan2(-f.x(), std::hypot(f.y(), f.z()));
    if (means.magCount > 0 && means.mag.squaredNorm() > 0.0) {
        result.yaw_rad = magneticHeading(means.mag, result.roll_rad, result.pitch_rad, params.declination_rad);
        result.headingFromMagnetometer = true;
    }
    result.bodyToNav = rotationFromRollPitchYaw(result.roll_rad, result.pitch_rad, result.yaw_rad);
    result.samplesUsed = means.count;
    return result;
}

}  // namespace footpath
