#pragma once

// Small pieces the heading and position sources share (header only: HDR, IPER, magnetometer).

#include "Result.h"
#include "nav/Attitude.h"
#include "nav/ErrorStateEkf.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace footpath::sources {

/// Angle wrapped to (-pi, pi].
inline double wrapAngle(double angle_rad)
{
    const double wrapped = std::remainder(angle_rad, 2.0 * M_PI);
    return wrapped <= -M_PI ? wrapped + 2.0 * M_PI : wrapped;
}

/// Yaw of the current attitude (z up, counter-clockwise from x).
inline double currentYaw(const ErrorStateEkf& ekf)
{
    return rollPitchYaw(ekf.state().bodyToNav).z();
}

/// A yaw measurement. C_est = (I + S(dphi)) C_true with C = Rz(yaw) Ry Rx: a small rotation dphi_z
/// about navigation z adds exactly dphi_z to the estimated yaw, so H selects dphi_z and the
/// innovation is the estimated minus the measured yaw.
inline void updateYaw(ErrorStateEkf& ekf, double innovation_rad, double std_rad)
{
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(1, ErrorStateEkf::kStates);
    h(0, ErrorStateEkf::kAtt + 2) = 1.0;
    ekf.updateRows(h, Eigen::VectorXd::Constant(1, wrapAngle(innovation_rad)),
                   Eigen::VectorXd::Constant(1, std_rad * std_rad));
}

/// Once per stance phase: true at the first stance sample that has been at rest for settle_s, so
/// a source measures once per step from a foot that has settled (the filter treats its updates as
/// independent; every sample of one stance would count the same heading 40 times).
class StanceTrigger {
public:
    explicit StanceTrigger(double settle_s) : settle_s_(settle_s) {}
    bool fires(bool stance, double time_s)
    {
        if (!stance) {
            inStance_ = false;
            return false;
        }
        if (!inStance_) {
            inStance_ = true;
            fired_ = false;
            start_s_ = time_s;
        }
        if (fired_ || time_s - start_s_ < settle_s_)
            return false;
        fired_ = true;
        return true;
    }

private:
    double settle_s_;
    bool inStance_ = false;
    bool fired_ = false;
    double start_s_ = 0.0;
};

/// Consecutive events with the same reason merged into one note: a span opens at the first, grows
/// with each further one and is written when another reason (or none) takes over.
class SpanNotes {
public:
    explicit SpanNotes(const char* method) : method_(method) {}
    /// reason empty: the method applied, an open span closes.
    void mark(double time_s, const std::string& reason, std::vector<MethodNote>& notes)
    {
        if (open_ && reason != reason_)
            close(notes);
        if (reason.empty())
            return;
        if (!open_) {
            open_ = true;
            reason_ = reason;
            note_ = MethodNote{method_, time_s, time_s, {}};
        }
        note_.end_s = time_s;
        message_ = reason;
    }
    /// The message written for the open span: the reason plus the latest figures (may change
    /// without splitting the span, e.g. the measured ratio).
    void detail(const std::string& message) { message_ = message; }
    void close(std::vector<MethodNote>& notes)
    {
        if (!open_)
            return;
        note_.message = message_;
        notes.push_back(note_);
        open_ = false;
    }
    void finish(double endTime_s, std::vector<MethodNote>& notes)
    {
        if (open_)
            note_.end_s = std::max(note_.end_s, endTime_s);
        close(notes);
    }

private:
    const char* method_;
    bool open_ = false;
    std::string reason_;
    std::string message_;
    MethodNote note_;
};

}  // namespace footpath::sources
