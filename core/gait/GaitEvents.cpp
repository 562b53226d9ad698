#include "gait/GaitEvents.h"

#include "gait/ApproximateRotation.h"

#include "nav/Attitude.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace footpath {

namespace {

/// A swing turns the foot faster than this about the sagittal axis, averaged over kSmoothing_s
/// (slow patients' swings peak near 3 rad/s, brisk walking at 6-8; a pivot in a U-turn may stay
/// under it and is not counted).
constexpr double kMinSwingPeak_radps = 1.0;
/// ... and the estimated foot moves at least this fast at the swing's peak (mid-swing feet move
/// at 2-5 m/s); a turn of the foot on the spot is no swing.
constexpr double kMinSwingSpeed_mps = 0.3;
/// The push-off dip ends, and the foot-slap dip begins, where the rate crosses zero next to the
/// swing; the dips' minima lie within this time of that crossing (60-80 ms in the IPOL walks).
constexpr double kDipSearch_s = 0.2;
/// Toe off and heel strike are where the rate is this share of the neighbouring dip's minimum.
constexpr double kEventLevel = 0.5;
/// The quiet part of a stance: |w| within this of the stance's quietest sample (foot-flat
/// walking feet rest below 0.5 rad/s; a sensor that never rests still has a quietest stretch).
constexpr double kQuietMargin_radps = 0.5;
/// The window the angular rate is averaged over to find the sagittal axis and the swings' peaks
/// (not the events, which need the sharp edges of the raw rate).
constexpr double kSmoothing_s = 0.1;
/// A swing lasts longer than this (0.3-0.5 s from a shuffle to a sprint); shorter ones are a heel
/// strike's impact ringing through the gyro.
constexpr double kMinSwing_s = 0.1;
/// A stance longer than this is standing, not walking: the stride is marked paused.
constexpr double kMaxWalkingStance_s = 2.0;

struct Swing {
    double toeOff = 0.0;  ///< fractional sample positions
    std::size_t peak = 0;
    double heelStrike = 0.0;
};

/// The part of the foot on the ground between two swings (or the start/end of the recording).
struct Stance {
    std::size_t quietFirst = 0, quietLast = 0;  ///< foot flat and heel off
    Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< mean over the quiet part
    Eigen::Matrix3d bodyToNav = Eigen::Matrix3d::Identity();  ///< in the middle of the quiet part
};

/// The angular rate averaged over kSmoothing_s around each sample, and the scatter matrix of
/// those averages (whose principal axis is the sagittal one): a heel strike rings through the gyro
/// for a few samples at up to 15 rad/s about any axis, and must neither tilt the axis nor pass for
/// a swing.
struct SmoothedRates {
    std::vector<Eigen::Vector3d> rates;
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
};

SmoothedRates smoothedRates(const std::vector<ImuSample>& samples)
{
    SmoothedRates smoothed;
    smoothed.rates.reserve(samples.size());
    // Component by component, as Eigen's vector sum and quotient compute them.
    double sumX = 0.0, sumY = 0.0, sumZ = 0.0;
    double xx = 0.0, xy = 0.0, xz = 0.0, yy = 0.0, yz = 0.0, zz = 0.0;
    const std::size_t n = samples.size();
    std::size_t first = 0, end = 0;  // the window [first, end)
    for (std::size_t k = 0; k < n; ++k) {
        const double time_s = samples[k].time_s;
        const double windowEnd_s = time_s + 0.5 * kSmoothing_s, windowStart_s = time_s - 0.5 * kSmoothing_s;
        for (; end < n && samples[end].time_s <= windowEnd_s; ++end) {
            const Eigen::Vector3d& gyr = samples[end].gyr_radps;
            sumX += gyr.x();
            sumY += gyr.y();
            sumZ += gyr.z();
        }
        for (; samples[first].time_s < windowStart_s; ++first) {
            const Eigen::Vector3d& gyr = samples[first].gyr_radps;
            sumX -= gyr.x();
            sumY -= gyr.y();
            sumZ -= gyr.z();
        }
        const auto count = static_cast<double>(end - first);
        const double x = sumX / count, y = sumY / count, z = sumZ / count;
        smoothed.rates.emplace_back(x, y, z);
        // rate * rate^T, symmetric: the six distinct products, each rounded as Eigen's outer product rounds it.
        xx += x * x;
        xy += x * y;
        xz += x * z;
        yy += y * y;
        yz += y * z;
        zz += z * z;
    }
    smoothed.scatter << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    return smoothed;
}

/// Whether the rate about the principal axis agrees with the foot turning toe-up while it moves
/// forwards: the sign of the sum over the moving samples of (w . axis) (C w . (v x up)), where
/// `along` holds w . axis. Toe rising while moving forwards is a positive turn about the axis to
/// the right of the motion (v x up). Samples slower than a swing are left out: their weight (the
/// speed) is small.
///
/// Only the sign matters, and building C from the angles with libm's sin and cos cost more than
/// the rest of the gait detection. No term exceeds its bound |w . axis| |w|_1 |v_h|_1 (C keeps
/// |w|), and mid-swing terms, which agree, come near theirs. So the sum is first taken over the
/// terms bounded above the mean with approximateSinCos (each then off by at most 12e-9 of its
/// bound), and decides if it outweighs the other terms' bounds; then over all terms; and only if
/// that lies within 1e-6 of the bounds' sum from zero (room for the approximation and for the
/// rounding of 1e8 terms), with the exact rotation. The answer is the exact sum's every time.
bool rateAgreesWithMotion(const std::vector<ImuSample>& samples, const GaitRates& rates, const Result& result)
{
    const std::vector<double>& along = rates.rawAlongAxis;
    // Each moving sample's bound; -1 marks the others.
    std::vector<double> termBounds;
    termBounds.reserve(samples.size());
    double bounds = 0.0;
    std::size_t moving = 0;
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const Eigen::Vector3d& velocity = result.velocity_mps[k];
        if (velocity.squaredNorm() < kMinSwingSpeed_mps * kMinSwingSpeed_mps) {
            termBounds.push_back(-1.0);
            continue;
        }
        termBounds.push_back(std::abs(along[k]) * rates.l1Norm[k]
                             * (std::abs(velocity.x()) + std::abs(velocity.y())));
        bounds += termBounds.back();
        ++moving;
    }
    const auto forEachMoving = [&termBounds](const auto& visit) {
        for (std::size_t k = 0; k < termBounds.size(); ++k)
            if (termBounds[k] >= 0.0)
                visit(k, termBounds[k]);
    };
    const auto approximateTerm = [&](std::size_t k) {
        return along[k] * approximateRateRightOfMotion(result.rollPitchYaw_rad[k], samples[k].gyr_radps, result.velocity_mps[k]);
    };
    const double meanBound = moving > 0 ? bounds / static_cast<double>(moving) : 0.0;
    const double margin = 1e-6 * bounds;
    double large = 0.0, smallBounds = 0.0;
    forEachMoving([&](std::size_t k, double bound) {
        if (bound >= meanBound)
            large += approximateTerm(k);
        else
            smallBounds += bound;
    });
    // False for NaN (an approximate angle beyond a thousand radians): the sums below decide. A sample
    // whose bound is NaN (a non-finite rate or velocity) is not a moving one and is in no sum.
    if (std::abs(large) > smallBounds + margin)
        return large > 0.0;
    double approximate = large;
    forEachMoving([&](std::size_t k, double bound) {
        if (bound < meanBound)
            approximate += approximateTerm(k);
    });
    if (std::abs(approximate) > margin)
        return approximate > 0.0;
    double agreement = 0.0;
    forEachMoving([&](std::size_t k, double) {
        const Eigen::Vector3d& rpy = result.rollPitchYaw_rad[k];
        agreement += along[k] * rateRightOfMotion(rotationFromRollPitchYaw(rpy.x(), rpy.y(), rpy.z()),
                                                  samples[k].gyr_radps, result.velocity_mps[k]);
    });
    return agreement >= 0.0;
}

/// Turns the rates about the principal axis into rates about the sagittal axis: signed so that
/// the rotation about it is positive while the estimated foot moves forwards through mid-swing
/// (speed weights the swing over push-off and foot slap, whose rotation is the other way).
void signAlongMotion(const std::vector<ImuSample>& samples, GaitRates& rates, const Result& result)
{
    // Turning the axis round negates every product of the dot products exactly: the rates about
    // -axis are these negated, to the last bit.
    if (!rateAgreesWithMotion(samples, rates, result)) {
        for (double& rate : rates.rawAlongAxis)
            rate = -rate;
        for (double& rate : rates.smoothedAlongAxis)
            rate = -rate;
    }
}

/// First sample at or after time t (times ascending).
std::size_t indexAtOrAfter(const std::vector<double>& time_s, double t)
{
    return static_cast<std::size_t>(std::lower_bound(time_s.begin(), time_s.end(), t) - time_s.begin());
}

/// Local maxima of the smoothed rate above kMinSwingPeak_radps where the foot moves; of peaks that
/// the rate does not leave the positive side between, only the highest (one swing, one peak).
std::vector<std::size_t> swingPeaks(const std::vector<double>& rate, const Result& result)
{
    std::vector<std::size_t> peaks;
    // The last sample before k where the rate was not positive: the rate left the positive side
    // since the last peak if it lies at or after that peak.
    std::optional<std::size_t> lastNotPositive;
    for (std::size_t k = 1; k + 1 < rate.size(); ++k) {
        if (!(rate[k - 1] > 0.0))
            lastNotPositive = k - 1;
        if (rate[k] < kMinSwingPeak_radps || rate[k] < rate[k - 1] || rate[k] <= rate[k + 1]
            || result.velocity_mps[k].norm() < kMinSwingSpeed_mps)
            continue;
        const bool sameSwing = !peaks.empty() && !(lastNotPositive && *lastNotPositive >= peaks.back());
        if (!sameSwing)
            peaks.push_back(k);
        else if (rate[k] > rate[peaks.back()])
            peaks.back() = k;
    }
    return peaks;
}

/// Where the rate crosses `level` between samples k and k + 1 (it must lie between their values),
/// as a position among the samples' times. A reading is the mean rate over the interval before
/// its time stamp (Xsens' delta-q, a decimating MEMS gyro; the strapdown assumes the same), so
/// rate sample k belongs half an interval earlier, at k - 0.5.
double crossing(const std::vector<double>& rate, std::size_t k, double level)
{
    const double span = rate[k + 1] - rate[k];
    return static_cast<double>(k) + (span == 0.0 ? 0.0 : (level - rate[k]) / span) - 0.5;
}

/// Toe off before the swing peaking at `peak`, not before sample `earliest`.
std::optional<double> toeOffBefore(const std::vector<double>& rate, const std::vector<double>& time_s,
                                   std::size_t peak, std::size_t earliest)
{
    std::size_t zero = peak;
    while (zero > earliest && rate[zero] > 0.0)
        --zero;
    if (rate[zero] > 0.0)
        return std::nullopt;  // no push-off dip: not a swing from the ground
    const std::size_t from = std::max(earliest, indexAtOrAfter(time_s, time_s[zero] - kDipSearch_s));
    const auto minimum = static_cast<std::size_t>(
        std::min_element(rate.begin() + static_cast<long>(from), rate.begin() + static_cast<long>(zero) + 1)
        - rate.begin());
    const double level = kEventLevel * rate[minimum];
    std::size_t k = minimum;
    while (k + 2 < rate.size() && rate[k + 1] < level)
        ++k;
    return crossing(rate, k, level);
}

/// Heel strike after the swing peaking at `peak`, not after sample `latest`.
std::optional<double> heelStrikeAfter(const std::vector<double>& rate, const std::vector<double>& time_s,
                                      std::size_t peak, std::size_t latest)
{
    std::size_t zero = peak;
    while (zero < latest && rate[zero] > 0.0)
        ++zero;
    if (rate[zero] > 0.0)
        return std::nullopt;  // no foot-slap dip: the swing does not end on the ground
    const std::size_t to = std::min(latest, indexAtOrAfter(time_s, time_s[zero] + kDipSearch_s));
    const auto minimum = static_cast<std::size_t>(
        std::min_element(rate.begin() + static_cast<long>(zero), rate.begin() + static_cast<long>(to) + 1)
        - rate.begin());
    const double level = kEventLevel * rate[minimum];
    std::size_t k = std::max<std::size_t>(minimum, 1);
    while (k > 1 && rate[k - 1] < level)
        --k;
    return crossing(rate, k - 1, level);
}

/// The time at a fractional sample position, interpolated.
double fractionalTime(const std::vector<double>& time_s, double position)
{
    const std::size_t below = std::min(time_s.size() - 1, static_cast<std::size_t>(std::floor(std::max(0.0, position))));
    if (below + 1 >= time_s.size())
        return time_s[below];
    return time_s[below] + (position - static_cast<double>(below)) * (time_s[below + 1] - time_s[below]);
}

std::vector<Swing> findSwings(const std::vector<double>& rate, const std::vector<double>& smoothedRate,
                              const Result& result)
{
    const std::vector<std::size_t> peaks = swingPeaks(smoothedRate, result);
    std::vector<Swing> swings;
    for (std::size_t i = 0; i < peaks.size(); ++i) {
        // A dip is searched only up to the neighbouring swings' peaks.
        const std::size_t earliest = i == 0 ? 0 : peaks[i - 1];
        const std::size_t latest = i + 1 == peaks.size() ? rate.size() - 1 : peaks[i + 1];
        const std::optional<double> toeOff = toeOffBefore(rate, result.time_s, peaks[i], earliest);
        const std::optional<double> heelStrike = heelStrikeAfter(rate, result.time_s, peaks[i], latest);
        if (!toeOff || !heelStrike)
            continue;
        if (fractionalTime(result.time_s, *heelStrike) - fractionalTime(result.time_s, *toeOff) < kMinSwing_s)
            continue;
        if (!swings.empty() && *toeOff <= swings.back().heelStrike)
            continue;  // overlaps the previous swing: a second peak of one swing
        swings.push_back({*toeOff, peaks[i], *heelStrike});
    }
    return swings;
}

Stance quietPart(const std::vector<double>& squaredNorm, const Result& result, std::size_t first, std::size_t last)
{
    Stance stance;
    // The square root grows with its argument: the smallest |w| is the root of the smallest |w|^2.
    double leastSquared = squaredNorm[first];
    for (std::size_t k = first; k <= last; ++k)
        leastSquared = std::min(leastSquared, squaredNorm[k]);
    const double quietest = std::sqrt(leastSquared);
    // The quiet part runs from the first quiet sample to the last: search from either end.
    const auto quiet = [&](std::size_t k) { return std::sqrt(squaredNorm[k]) <= quietest + kQuietMargin_radps; };
    std::size_t quietFirst = first;
    while (quietFirst <= last && !quiet(quietFirst))
        ++quietFirst;
    std::size_t quietLast = last;
    while (quietLast > quietFirst && !quiet(quietLast))
        --quietLast;
    if (quietFirst > last) {  // none (a NaN rate): as the running search left it
        quietFirst = last;
        quietLast = 0;
    }
    stance.quietFirst = quietFirst;
    stance.quietLast = quietLast;
    for (std::size_t k = stance.quietFirst; k <= stance.quietLast; ++k)
        stance.position_m += result.position_m[k];
    stance.position_m /= static_cast<double>(stance.quietLast - stance.quietFirst + 1);
    const Eigen::Vector3d& rpy = result.rollPitchYaw_rad[(stance.quietFirst + stance.quietLast) / 2];
    stance.bodyToNav = rotationFromRollPitchYaw(rpy.x(), rpy.y(), rpy.z());
    return stance;
}

std::size_t nearestSample(double position, std::size_t sampleCount)
{
    return std::min(sampleCount - 1, static_cast<std::size_t>(std::lround(std::max(0.0, position))));
}

GaitEvent eventAt(GaitEventKind kind, double position, const std::vector<double>& time_s)
{
    return {kind, nearestSample(position, time_s.size()), fractionalTime(time_s, position)};
}

GaitEvent eventAtSample(GaitEventKind kind, std::size_t k, const std::vector<double>& time_s)
{
    return {kind, k, time_s[k]};
}

/// Stance i lies between swing i - 1 and swing i; the first and last reach the recording's ends.
std::vector<Stance> stancesAround(const std::vector<Swing>& swings, const std::vector<double>& squaredNorm,
                                  const Result& result)
{
    std::vector<Stance> stances;
    const std::size_t n = squaredNorm.size();
    for (std::size_t i = 0; i <= swings.size(); ++i) {
        const std::size_t first = i == 0 ? 0 : nearestSample(swings[i - 1].heelStrike, n);
        const std::size_t last = i == swings.size() ? n - 1 : nearestSample(swings[i].toeOff, n);
        stances.push_back(quietPart(squaredNorm, result, first, std::max(first, last)));
    }
    return stances;
}

/// The turn about the vertical from one attitude to the next. Not a difference of yaw angles:
/// those are undefined for a sensor mounted near upright (pitch near 90 degrees).
double headingChange(const Eigen::Matrix3d& from, const Eigen::Matrix3d& to)
{
    const Eigen::Matrix3d turn = to * from.transpose();  // in the navigation frame
    return std::atan2(turn(1, 0) - turn(0, 1), turn(0, 0) + turn(1, 1));
}

/// The stride from the heel strike ending swing i to the one ending swing i + 1.
GaitStride makeStride(const std::vector<Swing>& swings, const std::vector<Stance>& stances, std::size_t i,
                      const Result& result)
{
    const std::vector<double>& time_s = result.time_s;
    const Stance& stance = stances[i + 1];
    const Stance& nextStance = stances[i + 2];
    GaitStride stride;
    stride.heelStrike = eventAt(GaitEventKind::HeelStrike, swings[i].heelStrike, time_s);
    stride.footFlat = eventAtSample(GaitEventKind::FootFlat, stance.quietFirst, time_s);
    stride.heelOff = eventAtSample(GaitEventKind::HeelOff, stance.quietLast, time_s);
    stride.toeOff = eventAt(GaitEventKind::ToeOff, swings[i + 1].toeOff, time_s);
    stride.nextHeelStrike = eventAt(GaitEventKind::HeelStrike, swings[i + 1].heelStrike, time_s);
    stride.strideTime_s = stride.nextHeelStrike.time_s - stride.heelStrike.time_s;
    stride.strideLength_m = (nextStance.position_m - stance.position_m).head<2>().norm();
    const double stanceTime_s = stride.toeOff.time_s - stride.heelStrike.time_s;
    if (stride.strideTime_s > 0.0) {
        stride.cadence_spm = cadenceOf(stride.strideTime_s);
        stride.stancePct = 100.0 * stanceTime_s / stride.strideTime_s;
        stride.swingPct = 100.0 - stride.stancePct;
    }
    double highest_m = stance.position_m.z();
    for (std::size_t k = stride.toeOff.sample; k <= stride.nextHeelStrike.sample; ++k)
        highest_m = std::max(highest_m, result.position_m[k].z());
    stride.clearance_m = highest_m - stance.position_m.z();
    stride.headingChange_rad = headingChange(stance.bodyToNav, nextStance.bodyToNav);
    stride.turning = std::abs(stride.headingChange_rad) > kTurningStrideThreshold_rad;
    stride.paused = stanceTime_s > kMaxWalkingStance_s;
    return stride;
}

std::vector<GaitEvent> eventsInOrder(const std::vector<Swing>& swings, const std::vector<Stance>& stances,
                                     const std::vector<double>& time_s)
{
    std::vector<GaitEvent> events;
    for (std::size_t i = 0; i < stances.size(); ++i) {
        if (i > 0) {
            events.push_back(eventAt(GaitEventKind::HeelStrike, swings[i - 1].heelStrike, time_s));
            events.push_back(eventAtSample(GaitEventKind::FootFlat, stances[i].quietFirst, time_s));
        }
        if (i < swings.size()) {
            events.push_back(eventAtSample(GaitEventKind::HeelOff, stances[i].quietLast, time_s));
            events.push_back(eventAt(GaitEventKind::ToeOff, swings[i].toeOff, time_s));
        }
    }
    return events;
}

/// Clears the flag over each swing's samples.
void clearSwings(const std::vector<Swing>& swings, std::vector<std::uint8_t>& stance)
{
    for (const Swing& swing : swings) {
        const std::size_t first = nearestSample(swing.toeOff, stance.size());
        const std::size_t last = nearestSample(swing.heelStrike, stance.size());
        if (first <= last)
            std::fill(stance.begin() + static_cast<long>(first), stance.begin() + static_cast<long>(last) + 1, 0);
    }
}

GaitSummary summarizeGait(const std::vector<GaitStride>& strides)
{
    GaitSummary summary;
    summary.strides = strides.size();
    for (const GaitStride& stride : strides) {
        summary.turningStrides += stride.turning;
        if (stride.turning || stride.paused)
            continue;
        ++summary.straightStrides;
        summary.strideLength_m += stride.strideLength_m;
        summary.strideTime_s += stride.strideTime_s;
        summary.stancePct += stride.stancePct;
        summary.swingPct += stride.swingPct;
        summary.clearance_m += stride.clearance_m;
    }
    if (summary.straightStrides > 0) {
        const double n = static_cast<double>(summary.straightStrides);
        summary.strideLength_m /= n;
        summary.strideTime_s /= n;
        summary.cadence_spm = cadenceOf(summary.strideTime_s);
        summary.stancePct /= n;
        summary.swingPct /= n;
        summary.clearance_m /= n;
    }
    return summary;
}

}  // namespace

const char* gaitEventKindName(GaitEventKind kind)
{
    switch (kind) {
    case GaitEventKind::HeelStrike: return "heel_strike";
    case GaitEventKind::FootFlat: return "foot_flat";
    case GaitEventKind::HeelOff: return "heel_off";
    case GaitEventKind::ToeOff: return "toe_off";
    }
    return "unknown";
}

GaitRates gaitRatesOf(const std::vector<ImuSample>& samples)
{
    const SmoothedRates smoothed = smoothedRates(samples);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(smoothed.scatter);
    const Eigen::Vector3d axis = solver.eigenvectors().col(2);  // eigenvalues ascending
    GaitRates rates;
    const std::size_t n = samples.size();
    rates.rawAlongAxis.reserve(n);
    rates.smoothedAlongAxis.reserve(n);
    rates.squaredNorm.reserve(n);
    rates.l1Norm.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Eigen::Vector3d& gyr = samples[k].gyr_radps;
        rates.rawAlongAxis.push_back(gyr.dot(axis));
        rates.smoothedAlongAxis.push_back(smoothed.rates[k].dot(axis));
        rates.squaredNorm.push_back(gyr.squaredNorm());
        rates.l1Norm.push_back(gyr.lpNorm<1>());
    }
    return rates;
}

void detectGaitEvents(const Recording& recording, Result& result)
{
    detectGaitEvents(recording, GaitRates{}, result);
}

void detectGaitEvents(const Recording& recording, GaitRates rates, Result& result)
{
    result.gaitEvents.clear();
    result.gaitStrides.clear();
    result.gait = GaitSummary{};
    const std::vector<ImuSample>& samples = recording.samples;
    result.gaitStance.assign(result.time_s.size(), 1);
    if (samples.size() < 3 || result.time_s.size() != samples.size() || result.velocity_mps.size() != samples.size())
        return;
    const auto fits = [&samples](const std::vector<double>& values) { return values.size() == samples.size(); };
    if (!fits(rates.rawAlongAxis) || !fits(rates.smoothedAlongAxis) || !fits(rates.squaredNorm) || !fits(rates.l1Norm))
        rates = gaitRatesOf(samples);  // none given (or not this recording's)
    signAlongMotion(samples, rates, result);
    const std::vector<Swing> swings = findSwings(rates.rawAlongAxis, rates.smoothedAlongAxis, result);
    if (swings.empty())
        return;
    const std::vector<Stance> stances = stancesAround(swings, rates.squaredNorm, result);
    for (std::size_t i = 0; i + 1 < swings.size(); ++i)
        result.gaitStrides.push_back(makeStride(swings, stances, i, result));
    result.gaitEvents = eventsInOrder(swings, stances, result.time_s);
    clearSwings(swings, result.gaitStance);
    result.gait = summarizeGait(result.gaitStrides);
}

std::vector<const GaitStride*> gaitStridesOfSteps(const Result& result)
{
    std::vector<const GaitStride*> strides;
    strides.reserve(result.steps.size());
    std::size_t next = 0;  // steps and strides are both in time order
    for (const Step& step : result.steps) {
        const double middle_s = 0.5 * (step.stanceStart_s + step.stanceEnd_s);
        while (next < result.gaitStrides.size() && result.gaitStrides[next].toeOff.time_s < middle_s)
            ++next;
        const bool holds = next < result.gaitStrides.size() && result.gaitStrides[next].heelStrike.time_s <= middle_s;
        strides.push_back(holds ? &result.gaitStrides[next++] : nullptr);
    }
    return strides;
}

}  // namespace footpath
