#include "SliderScale.h"

#include <algorithm>
#include <cmath>

namespace footpath {

namespace {

constexpr int kPositionsPerDecade = 100;
constexpr int kLinearSteps = 1000;
constexpr int kDecadesBelowMaximum = 6;
constexpr int kLogSignificantDigits = 3;
/// A linear slider from 0 spans up to this many times the default (rounded up to 1, 2, 2.5 or 5
/// times a power of ten) when the field's maximum lies beyond.
constexpr double kLinearSpanOfDefault = 10.0;

int decimalExponent(double value)
{
    return static_cast<int>(std::floor(std::log10(std::abs(value))));
}

/// value rounded to a multiple of 10^exponent. Dividing by an exact power of ten (rather than
/// multiplying by an inexact 10^-n) gives the double nearest the decimal, so 1e-4 stays 1e-4.
double roundToDecimalExponent(double value, int exponent)
{
    if (exponent >= 0) {
        const double quantum = std::pow(10.0, exponent);
        return std::round(value / quantum) * quantum;
    }
    const double scale = std::pow(10.0, -exponent);
    return std::round(value * scale) / scale;
}

double roundToSignificant(double value, int digits)
{
    return value == 0.0 ? 0.0 : roundToDecimalExponent(value, decimalExponent(value) - (digits - 1));
}

/// The lowest positive value of a logarithmic scale starting at 0 (see SliderScale).
double lowestPositiveFor(double maximum, double defaultValue)
{
    const double lowest = std::pow(10.0, decimalExponent(maximum) - kDecadesBelowMaximum);
    if (defaultValue > 0.0 && defaultValue < lowest)
        return std::pow(10.0, decimalExponent(defaultValue));
    return lowest;
}

/// The smallest 1, 2, 2.5 or 5 times a power of ten at or above value (> 0).
double roundNumberAtLeast(double value)
{
    const double power = std::pow(10.0, decimalExponent(value));
    for (const double mantissa : {1.0, 2.0, 2.5, 5.0})
        if (mantissa * power >= value * (1.0 - 1e-12))
            return mantissa * power;
    return 10.0 * power;
}

}  // namespace

SliderScale SliderScale::forField(const ParameterField& field, double defaultValue)
{
    SliderScale scale;
    scale.minimum_ = field.minimum;
    scale.maximum_ = field.maximum;
    scale.sliderMaximum_ = field.maximum;
    const bool positiveRangeSpansDecades = field.minimum > 0.0 && field.maximum / field.minimum >= 100.0;
    const bool smallValuesAboveZero =
        field.minimum == 0.0 && field.maximum > 0.0 && defaultValue < field.maximum / 100.0;
    if (!positiveRangeSpansDecades && !smallValuesAboveZero) {
        scale.steps_ = kLinearSteps;
        if (field.minimum == 0.0 && defaultValue > 0.0)
            scale.sliderMaximum_ = std::min(field.maximum, roundNumberAtLeast(kLinearSpanOfDefault * defaultValue));
        return scale;
    }
    scale.logarithmic_ = true;
    scale.zeroStop_ = smallValuesAboveZero;
    scale.lowestPositive_ =
        positiveRangeSpansDecades ? field.minimum : lowestPositiveFor(field.maximum, defaultValue);
    const double decades = std::log10(scale.maximum_ / scale.lowestPositive_);
    scale.steps_ = std::max(1, static_cast<int>(std::lround(decades * kPositionsPerDecade)));
    return scale;
}

int SliderScale::pageStep() const
{
    return logarithmic_ ? kPositionsPerDecade : steps_ / 10;
}

int SliderScale::toPosition(double value) const
{
    if (std::isnan(value))
        return 0;
    if (!logarithmic_) {
        const double fraction = (value - minimum_) / (sliderMaximum_ - minimum_);
        return std::clamp(static_cast<int>(std::lround(fraction * steps_)), 0, steps_);
    }
    if (zeroStop_ && value <= 0.0)
        return 0;
    const double clamped = std::clamp(value, lowestPositive_, maximum_);
    const double fraction = std::log10(clamped / lowestPositive_) / std::log10(maximum_ / lowestPositive_);
    return firstLogPosition() + static_cast<int>(std::lround(fraction * steps_));
}

double SliderScale::toValue(int position) const
{
    const int clamped = std::clamp(position, 0, maximumPosition());
    return logarithmic_ ? logValue(clamped) : linearValue(clamped);
}

double SliderScale::linearValue(int position) const
{
    // The ends are exact so the range limits are always reachable.
    if (position == 0)
        return minimum_;
    if (position == steps_)
        return sliderMaximum_;
    const double step = (sliderMaximum_ - minimum_) / steps_;
    return roundToDecimalExponent(minimum_ + position * step, decimalExponent(step));
}

double SliderScale::logValue(int position) const
{
    if (position < firstLogPosition())
        return 0.0;
    if (position == maximumPosition())
        return maximum_;
    const double fraction = static_cast<double>(position - firstLogPosition()) / steps_;
    return roundToSignificant(lowestPositive_ * std::pow(maximum_ / lowestPositive_, fraction),
                              kLogSignificantDigits);
}

}  // namespace footpath
