#pragma once

#include "Result.h"
#include "nav/Parameters.h"

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace footpath {

/// Trajectory CSV, one row per sample, z up:
/// time_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,roll_rad,pitch_rad,yaw_rad,c1,c2,c3,stance,gait_stance,
/// then the bias estimates gyro_bias_{x,y,z}_radps, acc_bias_{x,y,z}_mps2 (stance: the ZUPT's foot
/// at rest; gait_stance: heel strike to toe off). Numbers always use a dot.
void writeTrajectoryCsv(std::ostream& out, const Result& result);
/// Steps CSV: step,stance_start_s,stance_end_s,x_m,y_m,z_m,stride_length_m,stride_duration_s,
/// motion,baro_height_m,heel_strike_s,toe_off_s,gait_stance_pct,swing_pct,clearance_m,turning
/// (step: the stance phase, numbered from 1; the stride columns empty for step 1, which no stride
/// leads to; motion: motionClassName; baro_height_m empty without
/// a barometer; the gait columns describe the gait stride whose heel strike to toe off holds the
/// step's stance, empty when none does; turning 1 or 0).
void writeStepsCsv(std::ostream& out, const Result& result);
/// Summary as a header row and one value row; the motion-class counts and climbs follow the
/// figures of every recording, then the gait figures (gait_*: the gait section's means, empty
/// cells without a stride to average), the count of merged movements and of warnings.
void writeSummaryCsv(std::ostream& out, const Result& result);
/// Every parameter: name,value,unit,default,differs_from_default,group,description.
void writeParametersCsv(std::ostream& out, const Parameters& params);
/// Summary as one JSON object (samples, duration_s, steps, path_length_m, end_to_start_m, ...),
/// then "motion" (stair_steps_up, stair_steps_down, elevator_rides, stairs_climb_m,
/// stairs_descent_m), "gait" (strides, straight_strides, turning_strides and the means:
/// stride_time_s, stride_length_m, cadence_spm, stance_pct, swing_pct, clearance_m),
/// "merged_movements": the movements between stances that were no stride, as {start_s, end_s,
/// displacement_m, peak_rate_radps}, "warnings": the plausibility warnings as {kind, start_s,
/// end_s, message} objects, and "method_notes": what the methods skipped, as {method, start_s,
/// end_s, message}.
std::string summaryToJson(const Result& result);

/// Writes through a temporary file that is renamed at the end, so a failed write never leaves a
/// truncated file behind. Returns an error naming the path, or empty.
std::string writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace footpath
