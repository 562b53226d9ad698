#pragma once

#include <string>
#include <vector>

namespace footpath {

/// Which statistic decides that the foot is at rest (core/detect/). The values are stored in presets
/// by name (detectorChoiceNames): keep the order.
enum class DetectorKind : int {
    PaperC1C2C3 = 0,  ///< Guo 2015: |a| band, std of |a|, |w| bound, median filter (fixed thresholds)
    Shoe,             ///< Skog et al. 2010 GLRT, as in OpenShoe and pyshoe
    Ared,             ///< angular rate energy
    Amvd,             ///< acceleration moving variance
    Mbgtd,            ///< memory-based graph theoretic detector (pyshoe)
};

/// The error-state filter's size: 15 states estimate gyro and accelerometer biases (Guo 2015);
/// 9 states hold them at zero (Zheng et al. 2016's comparison; pyshoe's filter).
enum class FilterStates : int { Fifteen = 0, Nine };

/// What turns the inertial samples into a path: the error-state Kalman filter with its measurement
/// sources (Guo et al. 2015, the five-method EKF paper, Zheng et al. 2016); the same filter followed by a Rauch-Tung-Striebel smoother
/// (offline: every estimate uses the whole recording); or Feliz et al. 2009's per-stride velocity
/// de-drift (Feliz et al. 2009, no Kalman filter; offline only: it needs the stance that ends each stride).
/// Stored in presets by name: keep the order.
enum class EstimatorKind : int { Ekf = 0, Feliz, Smoother };

/// How a pressure difference becomes a height difference (Zheng et al. 2016, eq. 6-10).
enum class BarometerModel : int { Formula = 0, Linear };

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

    // Stance detector: which statistic, and how its threshold is found
    int detector = static_cast<int>(DetectorKind::Shoe);
    double zv_window_s = 0.02;           ///< statistic window (pyshoe: 25 ms, 5 samples at 200 Hz)
    double zv_sigma_acc_mps2 = 0.01;     ///< accelerometer noise the statistics are normalised by (OpenShoe)
    double zv_sigma_gyr_radps = 0.1 * 3.14159265358979323846 / 180.0;  ///< gyro noise (OpenShoe: 0.1 deg/s)
    bool zv_adaptive = true;             ///< threshold follows the motion; off: zv_log_threshold
    double zv_log_threshold = 4.5;       ///< fixed threshold, log10 of the normalised statistic
    double zv_adapt_window_s = 1.25;     ///< running minimum/maximum of the log statistic over this centred window
    double zv_adapt_offset_dec = 0.05;   ///< threshold = running minimum + this many decades
    double zv_adapt_fraction = 0.25;     ///< ... + this fraction of the way to the running maximum
    double zv_log_always = 4.0;          ///< below this (log10) the foot is always at rest
    double zv_log_never = 6.5;           ///< above this (log10) it never is
    double zv_min_stance_s = 0.05;       ///< shorter stance runs are dropped (the thr_time of the five-method EKF paper)

    // C1/C2/C3 stance detector (Guo 2015, section 2.3), used when detector is PaperC1C2C3
    double acc_min_mps2 = 9.0;       ///< C1 lower bound on |a|
    double acc_max_mps2 = 11.0;      ///< C1 upper bound on |a|
    double acc_std_max_mps2 = 0.5;   ///< C2: std of |a| over the window must be below this
    double window_half_s = 0.15;     ///< C2 half-window (paper: s = 15 samples at 100 Hz)
    double gyr_max_radps = 1.0;      ///< C3 bound on |w|
    double median_window_s = 0.11;   ///< median filter length (paper: 11 samples at 100 Hz)

    // Filter
    int filter_states = static_cast<int>(FilterStates::Nine);  ///< measured better (docs/method.md, "Defaults that differ from the paper")


    int estimator = static_cast<int>(EstimatorKind::Smoother);  ///< offline; live input runs the filter (docs/method.md, "The smoother")

    // Measurement sources (core/nav/MeasurementSources.h lists them in the order they are applied)
    bool use_zupt = true;
    bool use_zaru = false;  ///< needs the gyro bias states of the 15-state filter
    bool use_hdr = false;          ///< heuristic drift reduction (the five-method EKF paper): yaw pulled back on straight walks
    bool use_iper = false;         ///< position error reduction (the five-method EKF paper): rectilinear building, level floor
    bool use_zuna = false;         ///< zero navigation acceleration at mid-stance (the five-method EKF paper)
    bool use_baro = false;         ///< barometric height at each stance (Zheng et al. 2016)
    bool use_mag_heading = false;  ///< magnetometer heading during stance (Guo et al. 2015's future work)

    // HDR
    double hdr_lag_s = 1.0;            ///< heading now compared with the heading this long ago
    double hdr_threshold_rad = 0.08;   ///< a smaller difference is drift, a larger one a real turn (paper 0.15; 0.08 measured better on the ecg-xmu closed walks)
    double r_hdr_rad = 0.01;

    // IPER
    bool iper_axis_auto = true;        ///< building axis from the walk's dominant directions
    double iper_axis_rad = 0.0;        ///< the building's main axis (x of the navigation frame = 0)
    double iper_threshold_rad = 0.2;   ///< walking within this of an axis counts as along it
    double iper_window_s = 2.0;        ///< displacement windows
    double r_iper_m = 0.005;           ///< cross-axis displacement (small: the 9-state filter is confident of its position)
    double r_iper_height_m = 0.05;     ///< height at stance against the start height

    // ZUNA
    double zuna_reference_s = 3.0;     ///< static start averaged for the reference specific force
    double zuna_min_stance_s = 0.15;   ///< mid-stance: a stance run at least this long ...
    double zuna_margin_dec = 1.0;      ///< ... whose statistic is this far below the threshold
    double r_zuna_mps2 = 0.05;

    // Barometer and motion classes
    int baro_model = static_cast<int>(BarometerModel::Formula);
    double baro_linear_m_per_pa = 0.09;    ///< Zheng et al. 2016's experimental constant N
    double r_baro_m = 0.01;  ///< small because the gain is R against the filter's tiny vertical variance: 0.3 left ecg-xmu heights 1-6 m off
    double motion_level_max_m = 0.2;       ///< gamma_h (paper 0.16): ecg-xmu stance heights wander +-0.2 m on level floors
    double motion_elevator_var_pa2 = 100.0;  ///< mu_h (paper "300 Pa"): ecg-xmu rides 360-470 Pa^2, stairs and walking below 20

    // Magnetometer heading
    double r_mag_rad = 0.02;               ///< std per stance; the filter is sure of its heading, a looser R barely moves it
    double mag_norm_tolerance = 0.1;       ///< |m| within this fraction of its value at alignment
    double mag_dip_tolerance_rad = 0.087;  ///< dip angle within this of its value at alignment

    // Process noise Q: std per 10 ms step, per 3-block (Guo 2015, section 2.6)
    double q_att_rad = 3e-5;
    double q_gyro_bias_radps = 0.0;
    double q_pos_m = 0.0;
    double q_vel_mps = 4e-4;
    double q_acc_bias_mps2 = 0.0;

    // Measurement noise R: std
    double r_zupt_mps = 0.005;
    double r_zaru_radps = 0.1;
    /// Innovation gate of the aiding measurements (HDR, IPER, ZUNA, barometer, magnetometer): one
    /// whose normalised innovation y' S^-1 y lies above this quantile of its chi-square distribution
    /// is rejected and counted in the method notes; 0 turns the gate off. ZUPT and ZARU are never
    /// gated: they are the detector's decision, and a refused one would let the drift run.
    double gate_probability = 0.0;

    // Initial covariance P0: std per 3-block
    double p0_att_rad = 0.0;
    double p0_gyro_bias_radps = 1e-2;
    double p0_pos_m = 0.0;
    double p0_vel_mps = 0.0;
    double p0_acc_bias_mps2 = 1e-2;

    DetectorKind detectorKind() const { return static_cast<DetectorKind>(detector); }
    FilterStates filterStates() const { return static_cast<FilterStates>(filter_states); }
    EstimatorKind estimatorKind() const { return static_cast<EstimatorKind>(estimator); }
    BarometerModel barometerModel() const { return static_cast<BarometerModel>(baro_model); }

    /// Human-readable problems ("acc_min_mps2 (12) must be below acc_max_mps2 (11)"); empty if valid.
    std::vector<std::string> validate() const;
};

/// Guo 2015 as printed (section 2.3 detector, 2.6 tuning): the C1/C2/C3 detector with its fixed
/// thresholds, the 15-state filter with ZUPT and ZARU, Q attitude and velocity 1e-4. The defaults
/// differ where measurement on real walks said so (docs/accuracy.md).
Parameters guo2015Parameters();

/// When the pipeline reads a field: a condition on the other fields, kept with the method that owns
/// the field (a source's switch, the detector's kind, the filter's size), so a new method states it
/// where it is declared and every front end (the panel greys what is not read) follows.
struct FieldCondition {
    const char* id;                     ///< stable name for tests and logs ("hdr", "fixed_threshold")
    bool (*met)(const Parameters&);     ///< whether the pipeline reads the field with these values
    /// Why it is not read, for people; marked for translation in the "footpath::ParameterPanel"
    /// context. "%1" stands for the label of the chosen detector.
    const char* notUsedReason;
    const FieldCondition* within = nullptr;  ///< checked first (IPER's fixed axis within IPER)
};

/// Description of one field, so every front end walks the same list.
struct ParameterField {
    enum class Kind { Real, Flag, Choice };
    const char* name;
    Kind kind;
    double Parameters::*real;  ///< set when kind == Real
    bool Parameters::*flag;    ///< set when kind == Flag
    double minimum;            ///< allowed range (inclusive) for reals
    double maximum;
    const char* unit;
    const char* description;
    const char* group;  ///< "Alignment", "Detector", "Measurements", "Process noise", ...
    int Parameters::*choice = nullptr;  ///< set when kind == Choice: an index into choiceNames
    std::vector<const char*> choiceNames = {};  ///< names of the choices, as presets and --set spell them
    std::vector<const char*> choiceLabels = {};  ///< what a user reads ("SHOE (GLRT)")
    const FieldCondition* condition = nullptr;  ///< nullptr: always read
    /// A short name for people ("C2 bound on the std of |a|"), without the unit: front ends show
    /// labelWithUnit() and keep `name` for the tool tip, presets and --set.
    const char* label = "";
};

const std::vector<ParameterField>& parameterFields();
/// The unit as people write it (UTF-8): "m/s^2" -> "m/s²", "Pa^2" -> "Pa²"; unit-less fields ("x") give "".
std::string displayUnit(const ParameterField& field);
/// "C2 bound on the std of |a| (m/s²)"; the label alone for fields without a unit.
std::string labelWithUnit(const ParameterField& field);
const ParameterField* findParameterField(const std::string& name);

/// The first condition of field's that params does not meet, innermost last (a statistic-detector
/// field under the C1/C2/C3 detector gives "statistic_detectors", even if it is also a
/// fixed-threshold one); nullptr when the pipeline reads the field with these parameters.
const FieldCondition* unmetCondition(const ParameterField& field, const Parameters& params);

/// Builders of field rows, for the files that declare their methods' fields. Labels, descriptions
/// and groups are marked for translation in the "footpath::ParameterFields" context.
ParameterField realField(const char* name, const char* label, double Parameters::*member, double lo, double hi,
                         const char* unit, const char* description, const char* group,
                         const FieldCondition* condition = nullptr);
ParameterField flagField(const char* name, const char* label, bool Parameters::*member, const char* description,
                         const char* group, const FieldCondition* condition = nullptr);
ParameterField choiceField(const char* name, const char* label, int Parameters::*member,
                           std::vector<const char*> names, std::vector<const char*> labels, const char* description,
                           const char* group, const FieldCondition* condition = nullptr);

/// Equal in every field of parameterFields().
bool operator==(const Parameters& a, const Parameters& b);
inline bool operator!=(const Parameters& a, const Parameters& b) { return !(a == b); }

/// Reads a field by name as a number (flags as 0/1, choices as their index).
double parameterValue(const Parameters& params, const ParameterField& field);
/// The name of a choice field's current value ("shoe"); empty for other kinds.
std::string choiceName(const Parameters& params, const ParameterField& field);
/// Sets a field from text ("0.5", "1e-4", "true", "off", a choice's name); returns an error
/// message or empty.
std::string setParameter(Parameters& params, const std::string& name, const std::string& text);

}  // namespace footpath
