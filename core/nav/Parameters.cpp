#include "nav/Parameters.h"

#include "methods/FieldConditions.h"
#include "methods/MethodRegistry.h"

#include <QtGlobal>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace footpath {

ParameterField realField(const char* name, const char* label, double Parameters::*member, double lo, double hi,
                         const char* unit, const char* description, const char* group, const FieldCondition* condition)
{
    ParameterField field{name, ParameterField::Kind::Real, member, nullptr, lo, hi, unit, description, group};
    field.label = label;
    field.condition = condition;
    return field;
}

ParameterField flagField(const char* name, const char* label, bool Parameters::*member, const char* description,
                         const char* group, const FieldCondition* condition)
{
    ParameterField field{name, ParameterField::Kind::Flag, nullptr, member, 0.0, 1.0, "", description, group};
    field.label = label;
    field.condition = condition;
    return field;
}

ParameterField choiceField(const char* name, const char* label, int Parameters::*member,
                           std::vector<const char*> names, std::vector<const char*> labels, const char* description,
                           const char* group, const FieldCondition* condition)
{
    ParameterField field{name, ParameterField::Kind::Choice, nullptr, nullptr, 0.0,
                         static_cast<double>(names.size() - 1), "", description, group};
    field.label = label;
    field.choice = member;
    field.choiceNames = std::move(names);
    field.choiceLabels = std::move(labels);
    field.condition = condition;
    return field;
}

namespace {

using K = ParameterField::Kind;

template <class Method>
std::vector<const char*> tokensOf(const std::vector<Method>& methods)
{
    std::vector<const char*> tokens;
    for (const Method& method : methods)
        tokens.push_back(method.token);
    return tokens;
}

template <class Method>
std::vector<const char*> labelsOf(const std::vector<Method>& methods)
{
    std::vector<const char*> labels;
    for (const Method& method : methods)
        labels.push_back(method.label);
    return labels;
}

std::vector<const char*> detectorTokens() { return tokensOf(detectorMethods()); }
std::vector<const char*> detectorLabels() { return labelsOf(detectorMethods()); }
std::vector<const char*> estimatorTokens() { return tokensOf(estimatorMethods()); }
std::vector<const char*> estimatorLabels() { return labelsOf(estimatorMethods()); }

// Labels, descriptions, groups and choice labels are marked for translation (QT_TRANSLATE_NOOP
// leaves the literal as it is): the parameter panel shows them translated under this context.
std::vector<ParameterField> alignmentDetectorAndFilterFields()
{
    using P = Parameters;
    return {
        realField("alignment_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Alignment period"), &P::alignment_s,
             0.05, 600.0, "s",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Static period at the start used for alignment"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Alignment")),
        realField("gravity_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Gravity"), &P::gravity_mps2, 9.7, 9.9,
             "m/s^2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Local gravity"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Alignment")),
        realField("declination_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Magnetic declination"),
             &P::declination_rad, -M_PI, M_PI, "rad",
             QT_TRANSLATE_NOOP("footpath::ParameterFields",
                               "Magnetic declination subtracted from the compass heading"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Alignment")),
        choiceField("detector", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Stance detector"), &P::detector,
                    detectorTokens(), detectorLabels(),
                    QT_TRANSLATE_NOOP("footpath::ParameterFields", "Statistic that decides the foot is at rest"),
                    QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector")),
        realField("zv_window_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Statistic window"), &P::zv_window_s,
             0.0, 1.0, "s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Window of the detector statistic"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::statisticDetectors),
        realField("zv_sigma_acc_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Accelerometer noise"),
             &P::zv_sigma_acc_mps2, 1e-5, 10.0, "m/s^2",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Accelerometer noise the statistic is normalised by"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::detectorAccelerometer),
        realField("zv_sigma_gyr_radps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Gyroscope noise"),
             &P::zv_sigma_gyr_radps, 1e-6, 1.0, "rad/s",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Gyroscope noise the statistic is normalised by"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::detectorGyroscope),
        flagField("zv_adaptive", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Adaptive threshold"), &P::zv_adaptive,
             QT_TRANSLATE_NOOP("footpath::ParameterFields",
                               "Threshold follows the motion (off: a fixed threshold)"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::statisticDetectors),
        realField("zv_log_threshold", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Fixed threshold"),
             &P::zv_log_threshold, -5.0, 15.0, "log10",
             QT_TRANSLATE_NOOP("footpath::ParameterFields",
                               "Fixed threshold on the statistic (log10), when not adaptive"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::fixedThreshold),
        realField("zv_adapt_window_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Adaptive window"),
             &P::zv_adapt_window_s, 0.1, 10.0, "s",
             QT_TRANSLATE_NOOP("footpath::ParameterFields",
                               "Adaptive: window of the running minimum (about one gait cycle)"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::adaptiveThreshold),
        realField("zv_adapt_offset_dec", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Offset above the minimum"),
             &P::zv_adapt_offset_dec, 0.0, 5.0, "decades",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Adaptive: threshold above the running minimum"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::adaptiveThreshold),
        realField("zv_adapt_fraction", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Fraction towards the maximum"),
             &P::zv_adapt_fraction, 0.0, 1.0, "x",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Adaptive: threshold this fraction of the way from the "
                                                            "running minimum to the maximum"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::adaptiveThreshold),
        realField("zv_log_always", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Always at rest below"),
             &P::zv_log_always, -5.0, 15.0, "log10",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Adaptive: below this the foot is always at rest"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::adaptiveThreshold),
        realField("zv_log_never", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Never at rest above"),
             &P::zv_log_never, -5.0, 15.0, "log10",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Adaptive: above this the foot is never at rest"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::adaptiveThreshold),
        realField("zv_min_stance_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Shortest stance"),
             &P::zv_min_stance_s, 0.0, 2.0, "s",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Shorter stance runs are dropped"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::statisticDetectors),
        realField("acc_min_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C1 lower bound on |a|"),
             &P::acc_min_mps2, 0.0, 50.0, "m/s^2",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "C1: lower bound on |a|"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::paperDetector),
        realField("acc_max_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C1 upper bound on |a|"),
             &P::acc_max_mps2, 0.0, 200.0, "m/s^2",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "C1: upper bound on |a|"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::paperDetector),
        realField("acc_std_max_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C2 bound on the std of |a|"),
             &P::acc_std_max_mps2, 0.0, 20.0, "m/s^2",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "C2: std of |a| over the window must be below"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::paperDetector),
        realField("window_half_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C2 half-window"), &P::window_half_s,
             0.0, 2.0, "s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C2: half-window of the centred std"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::paperDetector),
        realField("gyr_max_radps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C3 bound on |ω|"), &P::gyr_max_radps,
             0.0, 20.0, "rad/s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "C3: upper bound on |w|"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::paperDetector),
        realField("median_window_s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Median filter length"),
             &P::median_window_s, 0.0, 2.0, "s",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Median filter length applied to C"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Detector"), &conditions::paperDetector),
        choiceField("filter_states", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Filter states"), &P::filter_states,
               {"15", "9"},
               {QT_TRANSLATE_NOOP("footpath::ParameterFields", "15 states (with biases)"),
                QT_TRANSLATE_NOOP("footpath::ParameterFields", "9 states (no bias states)")},
               QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                 "Error-state filter size: 15 estimates the sensor biases, 9 holds them at zero"),
               QT_TRANSLATE_NOOP("footpath::ParameterFields", "Filter")),
        choiceField("estimator", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Estimator"), &P::estimator,
               estimatorTokens(), estimatorLabels(),
               QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                 "Kalman filter with the measurements below, Feliz 2009's per-stride velocity "
                                 "de-drift, or the filter followed by a Rauch-Tung-Striebel smoother over the "
                                 "whole recording (offline; live input runs the filter)"),
               QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurements")),
    };
}

std::vector<ParameterField> noiseFields()
{
    using P = Parameters;
    return {
        realField("q_att_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q attitude"), &P::q_att_rad, 0.0, 1.0,
             "rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q attitude, std per 10 ms"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Process noise")),
        realField("q_gyro_bias_radps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q gyroscope bias"),
             &P::q_gyro_bias_radps, 0.0, 1.0, "rad/s",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q gyro bias, std per 10 ms"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Process noise"), &conditions::biasStates),
        realField("q_pos_m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q position"), &P::q_pos_m, 0.0, 1.0, "m",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q position, std per 10 ms"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Process noise")),
        realField("q_vel_mps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q velocity"), &P::q_vel_mps, 0.0, 1.0,
             "m/s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q velocity, std per 10 ms"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Process noise")),
        realField("q_acc_bias_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q accelerometer bias"),
             &P::q_acc_bias_mps2, 0.0, 1.0, "m/s^2",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Q accelerometer bias, std per 10 ms"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Process noise"), &conditions::biasStates),
        realField("r_zupt_mps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "R zero velocity"), &P::r_zupt_mps, 1e-6,
             10.0, "m/s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "R ZUPT, std"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurement noise")),
        realField("r_zaru_radps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "R zero angular rate"),
             &P::r_zaru_radps, 1e-6, 10.0, "rad/s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "R ZARU, std"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurement noise"), &conditions::zaru),
        realField("p0_att_rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 attitude"), &P::p0_att_rad, 0.0, 10.0,
             "rad", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 attitude, std"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Initial covariance")),
        realField("p0_gyro_bias_radps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 gyroscope bias"),
             &P::p0_gyro_bias_radps, 0.0, 10.0, "rad/s",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 gyro bias, std"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Initial covariance"), &conditions::biasStates),
        realField("p0_pos_m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 position"), &P::p0_pos_m, 0.0, 100.0,
             "m", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 position, std"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Initial covariance")),
        realField("p0_vel_mps", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 velocity"), &P::p0_vel_mps, 0.0,
             100.0, "m/s", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 velocity, std"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Initial covariance")),
        realField("p0_acc_bias_mps2", QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 accelerometer bias"),
             &P::p0_acc_bias_mps2, 0.0, 100.0, "m/s^2",
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "P0 accelerometer bias, std"),
             QT_TRANSLATE_NOOP("footpath::ParameterFields", "Initial covariance"), &conditions::biasStates),
        realField("gate_probability", QT_TRANSLATE_NOOP("footpath::ParameterFields", "Innovation gate"),
                  &P::gate_probability, 0.0, 0.999999, "x",
                  QT_TRANSLATE_NOOP("footpath::ParameterFields",
                                    "Aiding measurements (HDR, IPER, ZUNA, barometer, magnetometer) less likely than "
                                    "this under the filter's own uncertainty are rejected (chi-square test); 0: no "
                                    "gate. ZUPT and ZARU are never gated."),
                  QT_TRANSLATE_NOOP("footpath::ParameterFields", "Measurement noise")),
    };
}

/// The table in the order it has always had (presets and reports list it so): alignment, detector
/// and filter; the sources' switches; each source's own rows; the noise.
std::vector<ParameterField> makeFields()
{
    std::vector<ParameterField> fields = alignmentDetectorAndFilterFields();
    std::vector<ParameterField> sourceRows;
    for (const SourceMethod& source : sourceMethods()) {
        std::vector<ParameterField> rows = source.fields ? source.fields() : std::vector<ParameterField>{};
        if (rows.empty())
            continue;
        fields.push_back(rows.front());
        sourceRows.insert(sourceRows.end(), rows.begin() + 1, rows.end());
    }
    fields.insert(fields.end(), sourceRows.begin(), sourceRows.end());
    for (ParameterField& field : noiseFields())
        fields.push_back(std::move(field));
    return fields;
}

std::string formatNumber(double value)
{
    std::ostringstream out;
    out << value;
    return out.str();
}

bool parseFlag(const std::string& text, bool& value)
{
    std::string lower = text;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return std::tolower(ch); });
    if (lower == "1" || lower == "true" || lower == "on" || lower == "yes") {
        value = true;
        return true;
    }
    if (lower == "0" || lower == "false" || lower == "off" || lower == "no") {
        value = false;
        return true;
    }
    return false;
}

bool parseReal(const std::string& text, double& value)
{
    if (text.empty())
        return false;
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(value);
}

}  // namespace

Parameters guo2015Parameters()
{
    Parameters params;
    params.detector = static_cast<int>(DetectorKind::PaperC1C2C3);
    params.filter_states = static_cast<int>(FilterStates::Fifteen);
    params.use_zaru = true;
    params.q_att_rad = 1e-4;
    params.q_vel_mps = 1e-4;
    params.r_zupt_mps = 0.01;
    params.estimator = static_cast<int>(EstimatorKind::Ekf);  // the paper filters; it has no smoother
    return params;
}

const std::vector<ParameterField>& parameterFields()
{
    // Rebuilt when an extension has registered a method since (registration comes before any use
    // on other threads, MethodRegistry.h).
    static std::vector<ParameterField> fields = makeFields();
    static int builtAt = methodRegistryGeneration();
    if (builtAt != methodRegistryGeneration()) {
        fields = makeFields();
        builtAt = methodRegistryGeneration();
    }
    return fields;
}

std::string displayUnit(const ParameterField& field)
{
    std::string unit = field.unit;
    if (unit == "x")  // a fraction or factor: nothing to write
        return {};
    for (std::size_t at = unit.find("^2"); at != std::string::npos; at = unit.find("^2"))
        unit.replace(at, 2, "\u00b2");
    return unit;
}

std::string labelWithUnit(const ParameterField& field)
{
    const std::string unit = displayUnit(field);
    return unit.empty() ? std::string(field.label) : std::string(field.label) + " (" + unit + ")";
}

const ParameterField* findParameterField(const std::string& name)
{
    for (const ParameterField& field : parameterFields())
        if (name == field.name)
            return &field;
    return nullptr;
}

double parameterValue(const Parameters& params, const ParameterField& field)
{
    switch (field.kind) {
    case K::Real:
        return params.*field.real;
    case K::Flag:
        return params.*field.flag ? 1.0 : 0.0;
    case K::Choice:
        return static_cast<double>(params.*field.choice);
    }
    return 0.0;
}

std::string choiceName(const Parameters& params, const ParameterField& field)
{
    if (field.kind != K::Choice)
        return {};
    const int index = params.*field.choice;
    return index >= 0 && index < static_cast<int>(field.choiceNames.size()) ? field.choiceNames[index] : "?";
}

namespace {

std::string setChoice(Parameters& params, const ParameterField& field, const std::string& text)
{
    std::string known;
    for (std::size_t i = 0; i < field.choiceNames.size(); ++i) {
        if (text == field.choiceNames[i]) {
            params.*field.choice = static_cast<int>(i);
            return {};
        }
        known += (i > 0 ? ", " : "") + std::string(field.choiceNames[i]);
    }
    return "parameter '" + std::string(field.name) + "' expects one of " + known + ", got '" + text + "'";
}

}  // namespace

const FieldCondition* unmetCondition(const ParameterField& field, const Parameters& params)
{
    // The outermost unmet condition: "the detector is C1/C2/C3" says more than "the threshold is
    // fixed" when both hold.
    const FieldCondition* unmet = nullptr;
    for (const FieldCondition* condition = field.condition; condition; condition = condition->within)
        if (!condition->met(params))
            unmet = condition;
    return unmet;
}

bool operator==(const Parameters& a, const Parameters& b)
{
    for (const ParameterField& field : parameterFields())
        if (parameterValue(a, field) != parameterValue(b, field))
            return false;
    return true;
}

std::string setParameter(Parameters& params, const std::string& name, const std::string& text)
{
    const ParameterField* field = findParameterField(name);
    if (!field)
        return "unknown parameter '" + name + "'";
    if (field->kind == K::Choice)
        return setChoice(params, *field, text);
    if (field->kind == K::Flag) {
        if (!parseFlag(text, params.*field->flag))
            return "parameter '" + name + "' expects true/false, got '" + text + "'";
        return {};
    }
    double value = 0.0;
    if (!parseReal(text, value))
        return "parameter '" + name + "' expects a number, got '" + text + "'";
    params.*field->real = value;
    return {};
}

std::vector<std::string> Parameters::validate() const
{
    std::vector<std::string> problems;
    for (const ParameterField& field : parameterFields()) {
        if (field.kind == K::Choice) {
            const int index = this->*field.choice;
            if (index < 0 || index >= static_cast<int>(field.choiceNames.size()))
                problems.push_back(std::string(field.name) + " (" + std::to_string(index) + ") is not a known choice");
            continue;
        }
        if (field.kind != K::Real)
            continue;
        const double value = this->*field.real;
        if (!std::isfinite(value) || value < field.minimum || value > field.maximum)
            problems.push_back(std::string(field.name) + " (" + formatNumber(value) + ") must be between "
                               + formatNumber(field.minimum) + " and " + formatNumber(field.maximum)
                               + (displayUnit(field).empty() ? "" : " " + displayUnit(field)));  // m/s², as the window writes it
    }
    if (acc_min_mps2 >= acc_max_mps2)
        problems.push_back("acc_min_mps2 (" + formatNumber(acc_min_mps2) + ") must be below acc_max_mps2 ("
                           + formatNumber(acc_max_mps2) + ")");
    if (zv_log_always >= zv_log_never)
        problems.push_back("zv_log_always (" + formatNumber(zv_log_always) + ") must be below zv_log_never ("
                           + formatNumber(zv_log_never) + ")");
    return problems;
}

}  // namespace footpath
