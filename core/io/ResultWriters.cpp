#include "io/ResultWriters.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace footpath {

namespace {

// 9 significant digits keep sub-millimetre positions of a kilometre walk; %g keeps files small.
void put(std::ostream& out, double value, char separator)
{
    char buffer[32];
    const int length = std::snprintf(buffer, sizeof buffer, "%.9g", value);
    out.write(buffer, length);
    out.put(separator);
}

}  // namespace

void writeTrajectoryCsv(std::ostream& out, const Result& result)
{
    out << "time_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,roll_rad,pitch_rad,yaw_rad,c1,c2,c3,stance\n";
    const StanceFlags& flags = result.flags;
    for (std::size_t k = 0; k < result.time_s.size(); ++k) {
        put(out, result.time_s[k], ',');
        for (int axis = 0; axis < 3; ++axis)
            put(out, result.position_m[k][axis], ',');
        for (int axis = 0; axis < 3; ++axis)
            put(out, result.velocity_mps[k][axis], ',');
        for (int axis = 0; axis < 3; ++axis)
            put(out, result.rollPitchYaw_rad[k][axis], ',');
        out << int(flags.c1[k]) << ',' << int(flags.c2[k]) << ',' << int(flags.c3[k]) << ',' << int(flags.stance[k])
            << '\n';
    }
}

void writeStepsCsv(std::ostream& out, const Result& result)
{
    out << "step,stance_start_s,stance_end_s,x_m,y_m,z_m,stride_length_m,stride_duration_s\n";
    for (std::size_t i = 0; i < result.steps.size(); ++i) {
        const Step& step = result.steps[i];
        out << i << ',';
        put(out, step.stanceStart_s, ',');
        put(out, step.stanceEnd_s, ',');
        for (int axis = 0; axis < 3; ++axis)
            put(out, step.position_m[axis], ',');
        put(out, step.strideLength_m, ',');
        put(out, step.strideDuration_s, '\n');
    }
}

std::string summaryToJson(const Summary& s)
{
    std::ostringstream out;
    out.precision(10);
    out << "{\n"
        << "  \"samples\": " << s.samples << ",\n"
        << "  \"duration_s\": " << s.duration_s << ",\n"
        << "  \"stance_phases\": " << s.stancePhases << ",\n"
        << "  \"steps\": " << s.steps << ",\n"
        << "  \"path_length_m\": " << s.pathLength_m << ",\n"
        << "  \"end_to_start_m\": " << s.endToStart_m << ",\n"
        << "  \"end_to_start_pct\": " << s.endToStartPct << ",\n"
        << "  \"runtime_s\": " << s.runtime_s << "\n"
        << "}\n";
    return out.str();
}

std::string writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write)
{
    const std::string temporary = path + ".part";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out)
            return path + ": cannot open for writing: " + std::strerror(errno);
        write(out);
        out.flush();
        if (!out) {
            std::remove(temporary.c_str());
            return path + ": write failed (disk full?)";
        }
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        std::remove(temporary.c_str());
        return path + ": cannot replace the file: " + reason;
    }
    return {};
}

}  // namespace footpath
