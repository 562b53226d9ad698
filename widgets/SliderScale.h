#pragma once

#include "nav/Parameters.h"

namespace footpath {

/// Maps the integer positions of a slider to the values of one parameter field.
///
/// The rule for a logarithmic scale: a field is logarithmic when its range spans at least two
/// decades in the values people use, that is
///  - minimum > 0 and maximum / minimum >= 100 (r_*, alignment_s), or
///  - minimum == 0 and the default is below maximum / 100 (the q_* and p0_* noise values, many of
///    them 0 by default, whose useful values are orders of magnitude below the maximum).
/// A logarithmic scale from 0 keeps position 0 as an end stop meaning exactly 0; position 1 is the
/// lowest positive value, six decades below the maximum (lowered to the power of ten at or below
/// the default if the default is smaller, so the default is always on the scale). Everything else
/// (the detector thresholds, gravity, declination) is linear.
///
/// A linear field from 0 whose default is far below its maximum (the shortest stance: 0.05 of up
/// to 2 s) spans only up to the round number (1, 2, 2.5, 5 x 10^n) at or above ten times the default: over the whole
/// range a 50-pixel drag moved it from 0.02 to 0.66 s. Values beyond are typed; the slider then
/// rests at its end.
///
/// Resolution: 100 positions per decade (2.3 % per position) or 1000 over a linear range. Values
/// from a position are rounded to 3 significant digits (log) or to the power of ten at or below one
/// position (linear), so the numeric field shows tidy numbers; the rounding never moves a value to
/// another position.
class SliderScale {
public:
    static SliderScale forField(const ParameterField& field, double defaultValue);

    bool isLogarithmic() const { return logarithmic_; }
    bool hasZeroStop() const { return zeroStop_; }
    int maximumPosition() const { return firstLogPosition() + steps_; }
    int pageStep() const;
    int toPosition(double value) const;
    double toValue(int position) const;
    /// The value at the slider's far end: the field's maximum, or less where the slider spans
    /// only the useful part of a wide linear range.
    double sliderMaximum() const { return sliderMaximum_; }

private:
    int firstLogPosition() const { return zeroStop_ ? 1 : 0; }
    double linearValue(int position) const;
    double logValue(int position) const;

    double minimum_ = 0.0;
    double maximum_ = 1.0;
    double sliderMaximum_ = 1.0;
    double lowestPositive_ = 1.0;  ///< value at the first logarithmic position
    bool logarithmic_ = false;
    bool zeroStop_ = false;
    int steps_ = 1000;  ///< positions after the first (linear) or after the lowest positive (log)
};

}  // namespace footpath
