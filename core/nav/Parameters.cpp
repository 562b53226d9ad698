#include "nav/Parameters.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace footpath {

namespace {

using K = ParameterField::Kind;

ParameterField real(const char* name, double Parameters::*member, double lo, double hi, const char* unit,
                    const char* description, const char* group)
{
    return {name, K::Real, member, nullptr, lo, hi, unit, description, group};
}

ParameterField flag(const char* name, bool Parameters::*member, const char* description, const char* group)
{
    return {name, K::Flag, nullptr, member, 0.0, 1.0, "", description, group};
}

std::vector<ParameterField> makeFields()
{
    using P = Parameters;
    return {
        real("alignment_s", &P::alignment_s, 0.05, 600.0, "s", "Static period at the start used for alignment", "Alignment"),
        real("gravity_mps2", &P::gravity_mps2, 9.7, 9.9, "m/s^2", "Local gravity", "Alignment"),
        real("declination_rad", &P::declination_rad, -M_PI, M_PI, "rad", "Magnetic declination subtracted from the compass heading", "Alignment"),
        real("acc_min_mps2", &P::acc_min_mps2, 0.0, 50.0, "m/s^2", "C1: lower bound on |a|", "Detector"),
        real("acc_max_mps2", &P::acc_max_mps2, 0.0, 200.0, "m/s^2", "C1: upper bound on |a|", "Detector"),
        real("acc_std_max_mps2", &P::acc_std_max_mps2, 0.0, 20.0, "m/s^2", "C2: std of |a| over the window must be below", "Detector"),
        real("window_half_s", &P::window_half_s, 0.0, 2.0, "s", "C2: half-window of the centred std", "Detector"),
        real("gyr_max_radps", &P::gyr_max_radps, 0.0, 20.0, "rad/s", "C3: upper bound on |w|", "Detector"),
        real("median_window_s", &P::median_window_s, 0.0, 2.0, "s", "Median filter length applied to C", "Detector"),
        flag("use_zupt", &P::use_zupt, "Zero-velocity update during stance", "Measurements"),
        flag("use_zaru", &P::use_zaru, "Zero angular rate update during stance", "Measurements"),
        real("q_att_rad", &P::q_att_rad, 0.0, 1.0, "rad", "Q attitude, std per 10 ms", "Process noise"),
        real("q_gyro_bias_radps", &P::q_gyro_bias_radps, 0.0, 1.0, "rad/s", "Q gyro bias, std per 10 ms", "Process noise"),
        real("q_pos_m", &P::q_pos_m, 0.0, 1.0, "m", "Q position, std per 10 ms", "Process noise"),
        real("q_vel_mps", &P::q_vel_mps, 0.0, 1.0, "m/s", "Q velocity, std per 10 ms", "Process noise"),
        real("q_acc_bias_mps2", &P::q_acc_bias_mps2, 0.0, 1.0, "m/s^2", "Q accelerometer bias, std per 10 ms", "Process noise"),
        real("r_zupt_mps", &P::r_zupt_mps, 1e-6, 10.0, "m/s", "R ZUPT, std", "Measurement noise"),
        real("r_zaru_radps", &P::r_zaru_radps, 1e-6, 10.0, "rad/s", "R ZARU, std", "Measurement noise"),
        real("p0_att_rad", &P::p0_att_rad, 0.0, 10.0, "rad", "P0 attitude, std", "Initial covariance"),
        real("p0_gyro_bias_radps", &P::p0_gyro_bias_radps, 0.0, 10.0, "rad/s", "P0 gyro bias, std", "Initial covariance"),
        real("p0_pos_m", &P::p0_pos_m, 0.0, 100.0, "m", "P0 position, std", "Initial covariance"),
        real("p0_vel_mps", &P::p0_vel_mps, 0.0, 100.0, "m/s", "P0 velocity, std", "Initial covariance"),
        real("p0_acc_bias_mps2", &P::p0_acc_bias_mps2, 0.0, 100.0, "m/s^2", "P0 accelerometer bias, std", "Initial covariance"),
    };
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

const std::vector<ParameterField>& parameterFields()
{
    static const std::vector<ParameterField> fields = makeFields();
    return fields;
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
    return field.kind == K::Real ? params.*field.real : (params.*field.flag ? 1.0 : 0.0);
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
        if (field.kind != K::Real)
            continue;
        const double value = this->*field.real;
        if (!std::isfinite(value) || value < field.minimum || value > field.maximum)
            problems.push_back(std::string(field.name) + " (" + formatNumber(value) + ") must be between "
                               + formatNumber(field.minimum) + " and " + formatNumber(field.maximum) + " "
                               + field.unit);
    }
    if (acc_min_mps2 >= acc_max_mps2)
        problems.push_back("acc_min_mps2 (" + formatNumber(acc_min_mps2) + ") must be below acc_max_mps2 ("
                           + formatNumber(acc_max_mps2) + ")");
    return problems;
}

}  // namespace footpath
