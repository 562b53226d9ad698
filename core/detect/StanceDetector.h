#pragma once

#include "Recording.h"
#include "Result.h"
#include "nav/Parameters.h"

#include <vector>

namespace footpath {

/// Guo 2015 section 2.3: C1 (|a| within [acc_min, acc_max]), C2 (std of |a| over the centred
/// window below acc_std_max; the paper's text says "above", eq. 20 and the physics say below),
/// C3 (|w| below gyr_max), C = C1 & C2 & C3, then a median filter. Windows are durations, found
/// from the timestamps, so 100 Hz and 200 Hz recordings behave the same and gaps are honoured.
/// Offline and non-causal: the centred windows look ahead by window_half_s + median_window_s / 2.
StanceFlags detectStance(const std::vector<ImuSample>& samples, const Parameters& params);

/// Centred sliding standard deviation of values over samples with |t_j - t_k| <= halfWindow_s.
/// Near the ends the window holds only the samples that exist.
std::vector<double> centredStdDev(const std::vector<double>& times, const std::vector<double>& values,
                                  double halfWindow_s);

/// Binary median (majority vote) over samples with |t_j - t_k| <= window_s / 2; a tie keeps the
/// input value.
std::vector<std::uint8_t> medianFilter(const std::vector<double>& times, const std::vector<std::uint8_t>& flags,
                                       double window_s);

}  // namespace footpath
