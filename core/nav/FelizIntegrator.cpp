#include "nav/FelizIntegrator.h"

#include "nav/Alignment.h"
#include "nav/Attitude.h"
#include "nav/ErrorStateEkf.h"

#include <Eigen/Geometry>

#include <sstream>

namespace footpath {

namespace {

using Attitudes = std::vector<Eigen::Matrix3d>;
using Vectors = std::vector<Eigen::Vector3d>;

constexpr std::size_t kProgressInterval = 8192;

/// Reports the fraction done over the three passes; false once the callback asks to cancel.
class PassProgress {
public:
    PassProgress(const ProgressCallback& callback, std::size_t samples) : callback_(callback), samples_(samples) {}

    bool at(int pass, std::size_t k) const
    {
        if (!callback_ || k % kProgressInterval != 0)
            return true;
        const double withinPass = static_cast<double>(k) / static_cast<double>(samples_);
        return callback_((pass + withinPass) / kPasses);
    }

private:
    static constexpr double kPasses = 3.0;
    const ProgressCallback& callback_;
    std::size_t samples_;
};

/// Maximal runs of stance samples, inclusive.
std::vector<SampleRange> stanceRuns(const std::vector<std::uint8_t>& stance)
{
    std::vector<SampleRange> runs;
    for (std::size_t k = 0; k < stance.size(); ++k) {
        if (!stance[k])
            continue;
        if (k == 0 || !stance[k - 1])
            runs.push_back(SampleRange{k, k});
        runs.back().last = k;
    }
    return runs;
}

/// Pass 1: the attitude of every sample from the alignment and the integrated gyro, with the same
/// Pade rotation as the EKF's strapdown step (rate over (t_{k-1}, t_k]).
bool integrateGyro(const std::vector<ImuSample>& samples, const Eigen::Matrix3d& initial, const PassProgress& progress,
                   Attitudes& attitudes)
{
    attitudes.reserve(samples.size());
    attitudes.push_back(initial);
    for (std::size_t k = 1; k < samples.size(); ++k) {
        const double dt = samples[k].time_s - samples[k - 1].time_s;
        Eigen::Matrix3d next = attitudes.back() * padeRotation(samples[k].gyr_radps * dt);
        reorthonormalize(next);
        attitudes.push_back(next);
        if (!progress.at(0, k))
            return false;
    }
    return true;
}

/// The smallest rotation (about a horizontal axis, so the heading is kept) that turns the
/// navigation-frame specific force at rest onto +z.
Eigen::Matrix3d levellingRotation(const Eigen::Vector3d& navSpecificForce)
{
    const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(navSpecificForce, Eigen::Vector3d::UnitZ());
    return q.toRotationMatrix();
}

/// The navigation-frame specific force summed over the middle half of a stance run: its edges hold
/// the heel strike and the heel lift. (pyshoe-vicon mean 2D / 3D ARMSE with the whole run 0.063 /
/// 0.169 m, with the middle half 0.063 / 0.094 m; the ecg-xmu closed walks change either way.)
Eigen::Vector3d midStanceForce(const std::vector<ImuSample>& samples, const Attitudes& attitudes,
                               const SampleRange& run)
{
    const std::size_t quarter = (run.last - run.first) / 4;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t k = run.first + quarter; k <= run.last - quarter; ++k)
        sum += attitudes[k] * samples[k].acc_mps2;
    return sum;
}

/// Roll and pitch re-levelled from the accelerometer at each stance. Feliz et al. take the attitude
/// from the MTi's own orientation quaternion, which the Xsens filter keeps level with its gravity
/// reference; this is the equivalent here: the mean specific force of mid-stance, rotated with the
/// gyro attitude (which follows any roll of the foot within the stance), is turned onto vertical.
/// Without it a gyro bias tilts the attitude and gravity leaks into the horizontal velocity
/// (tst_feliz: 19 m instead of 0.3 m off after 100 m with 0.3 deg/s on the roll and pitch axes).
/// The cost: a horizontal accelerometer bias looks like a tilt at rest and tilts every stride, so
/// the height drifts more than with the gyro alone (pyshoe-vicon mean 3D ARMSE 0.094 against 0.076 m).
void relevelAtStances(const std::vector<ImuSample>& samples, const std::vector<SampleRange>& runs,
                      Attitudes& attitudes)
{
    Eigen::Matrix3d correction = Eigen::Matrix3d::Identity();
    std::size_t next = 0;
    for (const SampleRange& run : runs) {
        for (; next <= run.last; ++next)
            attitudes[next] = correction * attitudes[next];
        const Eigen::Matrix3d level = levellingRotation(midStanceForce(samples, attitudes, run));
        for (std::size_t k = run.first; k <= run.last; ++k)
            attitudes[k] = level * attitudes[k];
        correction = level * correction;
    }
    for (; next < attitudes.size(); ++next)
        attitudes[next] = correction * attitudes[next];
}

/// Pass 2: velocity from C f - g, restarted from zero after every stance sample, so at the first
/// stance sample after a swing it holds exactly the velocity that swing reached (its drift).
bool integrateVelocity(const std::vector<ImuSample>& samples, const Attitudes& attitudes,
                       const std::vector<std::uint8_t>& stance, double gravity_mps2, const PassProgress& progress,
                       Vectors& velocities)
{
    const Eigen::Vector3d gravity(0.0, 0.0, gravity_mps2);
    velocities.assign(samples.size(), Eigen::Vector3d::Zero());
    for (std::size_t k = 1; k < samples.size(); ++k) {
        const double dt = samples[k].time_s - samples[k - 1].time_s;
        const Eigen::Vector3d start = stance[k - 1] ? Eigen::Vector3d::Zero() : velocities[k - 1];
        velocities[k] = start + (attitudes[k] * samples[k].acc_mps2 - gravity) * dt;
        if (!progress.at(1, k))
            return false;
    }
    return true;
}

/// The drift of the swing (after, stanceStart) removed linearly in time: nothing at the sample
/// after which the foot left the ground (at rest, velocity zero), all of it at the stance start.
void removeSwingDrift(const std::vector<ImuSample>& samples, std::size_t after, std::size_t stanceStart,
                      Vectors& velocities)
{
    const Eigen::Vector3d drift = velocities[stanceStart];
    const double t0 = samples[after].time_s;
    const double span = samples[stanceStart].time_s - t0;
    for (std::size_t k = after + 1; k < stanceStart; ++k)
        velocities[k] -= drift * ((samples[k].time_s - t0) / span);
}

void noteUncorrectedEnd(const std::vector<ImuSample>& samples, std::size_t first, std::vector<MethodNote>& notes)
{
    std::ostringstream message;
    message << "not applied over [" << samples[first].time_s << ", " << samples.back().time_s
            << "] s: no stance ends the last swing, so its velocity drift is left in";
    notes.push_back(MethodNote{"feliz", samples[first].time_s, samples.back().time_s, message.str()});
}

/// Every swing that a stance ends is de-drifted and every stance sample gets velocity zero. A walk
/// that starts in motion is taken to start at rest (as the alignment does).
void deDrift(const std::vector<ImuSample>& samples, const std::vector<SampleRange>& runs, Vectors& velocities,
             std::vector<MethodNote>& notes)
{
    std::size_t lastAtRest = 0;
    for (const SampleRange& run : runs) {
        if (run.first > lastAtRest + 1)
            removeSwingDrift(samples, lastAtRest, run.first, velocities);
        for (std::size_t k = run.first; k <= run.last; ++k)
            velocities[k].setZero();
        lastAtRest = run.last;
    }
    if (lastAtRest + 1 < samples.size() && !runs.empty())
        noteUncorrectedEnd(samples, lastAtRest + 1, notes);
}

/// Pass 3: positions from the de-drifted velocities (trapezoid, as the strapdown step), recorded
/// with the attitude; the bias vectors hold zeros (this method estimates none).
bool recordPath(const std::vector<ImuSample>& samples, const Attitudes& attitudes, const Vectors& velocities,
                const PassProgress& progress, Result& result)
{
    reserveResult(result, samples.size());
    NavState state;
    for (std::size_t k = 0; k < samples.size(); ++k) {
        if (k > 0)
            state.position_m += 0.5 * (velocities[k - 1] + velocities[k]) * (samples[k].time_s - samples[k - 1].time_s);
        state.velocity_mps = velocities[k];
        state.bodyToNav = attitudes[k];
        recordState(result, samples[k].time_s, state);
        if (!progress.at(2, k))
            return false;
    }
    return true;
}

}  // namespace

bool runFelizIntegrator(const Recording& recording, const Parameters& params, const ProgressCallback& progress,
                        Result& result)
{
    const std::vector<ImuSample>& samples = recording.samples;
    const std::vector<std::uint8_t>& stance = result.flags.stance;
    const PassProgress passes(progress, samples.size());
    const std::vector<SampleRange> runs = stanceRuns(stance);
    Attitudes attitudes;
    if (!integrateGyro(samples, alignInitialAttitude(samples, stance, params).bodyToNav, passes, attitudes))
        return false;
    relevelAtStances(samples, runs, attitudes);
    Vectors velocities;
    if (!integrateVelocity(samples, attitudes, stance, params.gravity_mps2, passes, velocities))
        return false;
    deDrift(samples, runs, velocities, result.methodNotes);
    return recordPath(samples, attitudes, velocities, passes, result);
}

}  // namespace footpath
