#pragma once

#include <string>
#include <vector>

namespace footpath {

/// Every tunable of the pipeline. Field names here are the names the GUI sliders, the CLI's
/// `--set name=value`, the JSON presets and the reports use (see parameterFields()).
///
/// Noise values are standard deviations per 10 ms step (the paper's 100 Hz); the filter scales
/// the variances by dt / 0.01 s so a 200 Hz recording gets the same noise per second.
struct Parameters {
    // Initial alignment
    double alignment_s = 1.0;        ///< static period at the start used for roll/pitch/heading
    double gravity_mps2 = 9.81;
    double declination_rad = 0.0;    ///< magnetic declination M_d, subtracted from the compass heading

    // C1/C2/C3 stance detector (Guo 2015, section 2.3)
    double acc_min_mps2 = 9.0;       ///< C1 lower bound on |a|
    double acc_max_mps2 = 11.0;      ///< C1 upper bound on |a|
    double acc_std_max_mps2 = 0.5;   ///< C2: std of |a| over the window must be below this
    double window_half_s = 0.15;     ///< C2 half-window (paper: s = 15 samples at 100 Hz)
    double gyr_max_radps = 1.0;      ///< C3 bound on |w|
    double median_window_s = 0.11;   ///< median filter length (paper: 11 samples at 100 Hz)

    // Measurement sources
    bool use_zupt = true;
    bool use_zaru = true;

    // Process noise Q: std per 10 ms step, per 3-block (Guo 2015, section 2.6)
    double q_att_rad = 1e-4;
    double q_gyro_bias_radps = 0.0;
    double q_pos_m = 0.0;
    double q_vel_mps = 1e-4;
    double q_acc_bias_mps2 = 0.0;

    // Measurement noise R: std
    double r_zupt_mps = 0.01;
    double r_zaru_radps = 0.1;

    // Initial covariance P0: std per 3-block
    double p0_att_rad = 0.0;
    double p0_gyro_bias_radps = 1e-2;
    double p0_pos_m = 0.0;
    double p0_vel_mps = 0.0;
    double p0_acc_bias_mps2 = 1e-2;

    /// Human-readable problems ("acc_min_mps2 (12) must be below acc_max_mps2 (11)"); empty if valid.
    std::vector<std::string> validate() const;
};

/// Description of one field, so every front end walks the same list.
struct ParameterField {
    enum class Kind { Real, Flag };
    const char* name;
    Kind kind;
    double Parameters::*real;  ///< set when kind == Real
    bool Parameters::*flag;    ///< set when kind == Flag
    double minimum;            ///< allowed range (inclusive) for reals
    double maximum;
    const char* unit;
    const char* description;
    const char* group;  ///< "Alignment", "Detector", "Measurements", "Process noise", ...
};

const std::vector<ParameterField>& parameterFields();
const ParameterField* findParameterField(const std::string& name);

/// Equal in every field of parameterFields().
bool operator==(const Parameters& a, const Parameters& b);
inline bool operator!=(const Parameters& a, const Parameters& b) { return !(a == b); }

/// Reads a field by name as a number (flags as 0/1).
double parameterValue(const Parameters& params, const ParameterField& field);
/// Sets a field from text ("0.5", "1e-4", "true", "off"); returns an error message or empty.
std::string setParameter(Parameters& params, const std::string& name, const std::string& text);

}  // namespace footpath
