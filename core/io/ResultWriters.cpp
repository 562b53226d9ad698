#include "io/ResultWriters.h"

#include "gait/GaitEvents.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace footpath {

namespace {

// 10 significant digits keep sub-millimetre positions of a 100 km walk and the biases' last
// digits; std::to_chars writes a dot whatever the C locale says (Qt sets it from the
// environment, which would give "9,81" under a German locale with printf).
void putNumber(std::ostream& out, double value)
{
    char buffer[40];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 10).ptr;
    out.write(buffer, end - buffer);
}

void put(std::ostream& out, double value, char separator)
{
    putNumber(out, value);
    out.put(separator);
}

void putVector(std::ostream& out, const Eigen::Vector3d& v, char lastSeparator = ',')
{
    put(out, v.x(), ',');
    put(out, v.y(), ',');
    put(out, v.z(), lastSeparator);
}

/// A CSV cell that may hold commas or quotes.
std::string quoted(const std::string& text)
{
    if (text.find_first_of(",\"\n") == std::string::npos)
        return text;
    std::string out = "\"";
    for (char ch : text)
        out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return out + "\"";
}

/// text as a JSON string literal: quotes, backslashes and control characters escaped; UTF-8
/// passes through as JSON allows.
std::string jsonString(const std::string& text)
{
    std::string out = "\"";
    for (char ch : text) {
        if (ch == '"' || ch == '\\') {
            out += '\\';
            out += ch;
        } else if (static_cast<unsigned char>(ch) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(ch));
            out += escaped;
        } else {
            out += ch;
        }
    }
    return out + "\"";
}

}  // namespace

void writeTrajectoryCsv(std::ostream& out, const Result& result)
{
    out << "time_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,roll_rad,pitch_rad,yaw_rad,c1,c2,c3,stance,gait_stance,"
           "gyro_bias_x_radps,gyro_bias_y_radps,gyro_bias_z_radps,acc_bias_x_mps2,acc_bias_y_mps2,acc_bias_z_mps2\n";
    const StanceFlags& flags = result.flags;
    for (std::size_t k = 0; k < result.time_s.size(); ++k) {
        put(out, result.time_s[k], ',');
        putVector(out, result.position_m[k]);
        putVector(out, result.velocity_mps[k]);
        putVector(out, result.rollPitchYaw_rad[k]);
        out << int(flags.c1[k]) << ',' << int(flags.c2[k]) << ',' << int(flags.c3[k]) << ',' << int(flags.stance[k])
            << ',' << (k < result.gaitStance.size() ? int(result.gaitStance[k]) : 0) << ',';
        putVector(out, result.gyroBias_radps[k]);
        putVector(out, result.accBias_mps2[k], '\n');
    }
}

namespace {

/// The gait columns of the steps CSV, empty cells where no stride matches the step.
void putGaitCells(std::ostream& out, const GaitStride* stride)
{
    if (!stride) {
        out << ",,,,,,";
        return;
    }
    out << ',';
    put(out, stride->heelStrike.time_s, ',');
    put(out, stride->toeOff.time_s, ',');
    put(out, stride->stancePct, ',');
    put(out, stride->swingPct, ',');
    put(out, stride->clearance_m, ',');
    out << int(stride->turning);
}

}  // namespace

void writeStepsCsv(std::ostream& out, const Result& result)
{
    out << "step,stance_start_s,stance_end_s,x_m,y_m,z_m,stride_length_m,stride_duration_s,motion,baro_height_m,"
           "heel_strike_s,toe_off_s,gait_stance_pct,swing_pct,clearance_m,turning\n";
    const std::vector<const GaitStride*> gaitStrides = gaitStridesOfSteps(result);
    for (std::size_t i = 0; i < result.steps.size(); ++i) {
        const Step& step = result.steps[i];
        out << i + 1 << ',';  // numbered from 1, as the window's step table and the report number them
        put(out, step.stanceStart_s, ',');
        put(out, step.stanceEnd_s, ',');
        putVector(out, step.position_m);
        if (i == 0)
            out << ",,";  // the first stance has no stride before it: empty, not a stride of 0 m in 0 s
        else {
            put(out, step.strideLength_m, ',');
            put(out, step.strideDuration_s, ',');
        }
        out << motionClassName(step.motion) << ',';
        // An empty cell, not "nan", where there is no barometer: spreadsheets read it as missing.
        if (!std::isnan(step.baroHeight_m))
            putNumber(out, step.baroHeight_m);
        putGaitCells(out, gaitStrides[i]);
        out << '\n';
    }
}

namespace {

void putMotionJson(std::ostream& out, const Summary& s)
{
    out << "  \"motion\": {\"stair_steps_up\": " << s.stairStepsUp << ", \"stair_steps_down\": " << s.stairStepsDown
        << ", \"elevator_rides\": " << s.elevatorRides << ", \"stairs_climb_m\": " << s.stairsClimb_m
        << ", \"stairs_descent_m\": " << s.stairsDescent_m << "},\n";
}

void putWarningsJson(std::ostream& out, const std::vector<PlausibilityWarning>& warnings)
{
    out << "  \"warnings\": [";
    for (std::size_t i = 0; i < warnings.size(); ++i) {
        const PlausibilityWarning& w = warnings[i];
        out << (i == 0 ? "\n" : ",\n") << "    {\"kind\": " << jsonString(warningKindName(w.kind))
            << ", \"start_s\": " << w.start_s << ", \"end_s\": " << w.end_s
            << ", \"message\": " << jsonString(w.message) << "}";
    }
    out << (warnings.empty() ? "]" : "\n  ]");
}

void putMethodNotesJson(std::ostream& out, const std::vector<MethodNote>& notes)
{
    out << "  \"method_notes\": [";
    for (std::size_t i = 0; i < notes.size(); ++i) {
        const MethodNote& n = notes[i];
        out << (i == 0 ? "\n" : ",\n") << "    {\"method\": " << jsonString(n.method)
            << ", \"start_s\": " << n.start_s << ", \"end_s\": " << n.end_s
            << ", \"message\": " << jsonString(n.message) << "}";
    }
    out << (notes.empty() ? "]" : "\n  ]");
}

void putGaitJson(std::ostream& out, const GaitSummary& g)
{
    out << "  \"gait\": {\"strides\": " << g.strides << ", \"straight_strides\": " << g.straightStrides
        << ", \"turning_strides\": " << g.turningStrides << ", \"stride_time_s\": " << g.strideTime_s
        << ", \"stride_length_m\": " << g.strideLength_m << ", \"cadence_spm\": " << g.cadence_spm
        << ", \"stance_pct\": " << g.stancePct << ", \"swing_pct\": " << g.swingPct
        << ", \"clearance_m\": " << g.clearance_m << "},\n";
}

void putMergedMovementsJson(std::ostream& out, const std::vector<MergedMovement>& merged)
{
    out << "  \"merged_movements\": [";
    for (std::size_t i = 0; i < merged.size(); ++i) {
        const MergedMovement& m = merged[i];
        out << (i == 0 ? "\n" : ",\n") << "    {\"start_s\": " << m.start_s << ", \"end_s\": " << m.end_s
            << ", \"displacement_m\": " << m.displacement_m << ", \"peak_rate_radps\": " << m.peakRate_radps << "}";
    }
    out << (merged.empty() ? "]" : "\n  ]");
}

}  // namespace

std::string summaryToJson(const Result& result)
{
    const Summary& s = result.summary;
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
        << "  \"runtime_s\": " << s.runtime_s << ",\n";
    putMotionJson(out, s);
    putGaitJson(out, result.gait);
    putMergedMovementsJson(out, result.mergedMovements);
    out << ",\n";
    putWarningsJson(out, result.warnings);
    out << ",\n";
    putMethodNotesJson(out, result.methodNotes);
    out << "\n}\n";
    return out.str();
}

void writeSummaryCsv(std::ostream& out, const Result& result)
{
    const Summary& s = result.summary;
    const GaitSummary& g = result.gait;
    out << "samples,duration_s,stance_phases,steps,path_length_m,end_to_start_m,end_to_start_pct,runtime_s,"
           "stair_steps_up,stair_steps_down,elevator_rides,stairs_climb_m,stairs_descent_m,"
           "gait_strides,gait_stride_time_s,gait_stride_length_m,gait_cadence_spm,gait_stance_pct,gait_swing_pct,"
           "gait_clearance_m,merged_movements,warnings\n";
    out << s.samples << ',';
    put(out, s.duration_s, ',');
    out << s.stancePhases << ',' << s.steps << ',';
    put(out, s.pathLength_m, ',');
    put(out, s.endToStart_m, ',');
    put(out, s.endToStartPct, ',');
    put(out, s.runtime_s, ',');
    out << s.stairStepsUp << ',' << s.stairStepsDown << ',' << s.elevatorRides << ',';
    put(out, s.stairsClimb_m, ',');
    put(out, s.stairsDescent_m, ',');
    out << g.strides << ',';
    if (g.straightStrides == 0)
        out << ",,,,,,";  // no stride to average: empty cells, not zeros
    else
        for (const double figure : {g.strideTime_s, g.strideLength_m, g.cadence_spm, g.stancePct, g.swingPct, g.clearance_m})
            put(out, figure, ',');
    out << result.mergedMovements.size() << ',' << result.warnings.size() << '\n';
}

void writeParametersCsv(std::ostream& out, const Parameters& params)
{
    const Parameters defaults;
    out << "name,value,unit,default,differs_from_default,group,description\n";
    for (const ParameterField& field : parameterFields()) {
        const double value = parameterValue(params, field);
        const double standard = parameterValue(defaults, field);
        out << field.name << ',';
        put(out, value, ',');
        out << quoted(field.unit) << ',';
        put(out, standard, ',');
        out << (value != standard ? 1 : 0) << ',' << quoted(field.group) << ',' << quoted(field.description) << '\n';
    }
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
