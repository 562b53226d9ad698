#pragma once

#include "nav/BulkAllocator.h"

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace footpath {

/// The record of one measurement update, z = H dx + noise with gain K and S = H P H^T + R, that
/// the smoother's backward pass runs backwards. It is on the N states the filter runs (9 or 15,
/// ErrorStateEkf::filterIndex order) and flat, in doubles:
///   [rows, selects, H, K, S^-1 z, S^-1, length]
/// - selects 1: H is rows of the identity, stored as the running states' indices (ZUPT, ZARU);
///   selects 0: H is stored rows x N, row by row.
/// - K is N x rows and S^-1 rows x rows, column by column.
/// - Each record ends with its length, so a sample's records can be read last one first.
/// The filter writes the records as it makes its updates (ErrorStateEkf::setRecordUpdates); the
/// smoother copies a sample's records into its store as they are (RtsSmoother::capture) and
/// reads them there (RtsSmoother.cpp, StoredUpdate).
namespace update_record {

/// No measurement of the filter has more rows than it has states.
constexpr int kMaxRows = 15;

/// Records one after the other. Appending one does not zero it first (BulkAllocator), as every
/// double of it is written.
using Records = std::vector<double, BulkAllocator<double>>;

/// A record's length in doubles.
constexpr std::size_t length(int runningStates, int rows, bool selects)
{
    const auto n = static_cast<std::size_t>(runningStates), m = static_cast<std::size_t>(rows);
    return 2 + (selects ? m : m * n) + n * m + m + m * m + 1;
}

/// Appends the record of an update whose H selects running states, none of them position: the
/// usual ZUPT and ZARU, with every size known at compile time (a stance sample makes one, and
/// the generic loops of append() cost as much as the rest of recording a sample).
template <int N, int Rows>
void appendSelecting(Records& records, const Eigen::Matrix<int, Rows, 1>& runningStates,
                     const Eigen::Matrix<double, N, Rows>& gain, const Eigen::Matrix<double, Rows, 1>& weightedInnovation,
                     const Eigen::Matrix<double, Rows, Rows>& inverseS)
{
    constexpr std::size_t size = length(N, Rows, true);
    const std::size_t begin = records.size();
    records.resize(begin + size);
    double* out = records.data() + begin;
    *out++ = Rows;
    *out++ = 1.0;
    for (int row = 0; row < Rows; ++row)
        *out++ = runningStates(row);
    out = std::copy_n(gain.data(), N * Rows, out);  // column-major: the columns of K, as stored
    out = std::copy_n(weightedInnovation.data(), Rows, out);
    out = std::copy_n(inverseS.data(), Rows * Rows, out);
    *out = static_cast<double>(size);
}

/// Any update, as the filter made it: H is rows of the identity at selectedStates (when not
/// empty) or h; gain, weightedInnovation and inverseS on all 15 states. For append().
struct GeneralUpdate {
    Eigen::VectorXi selectedStates;
    Eigen::MatrixXd h;                   ///< rows x 15, when selectedStates is empty
    Eigen::MatrixXd gain;                ///< K, 15 x rows
    Eigen::VectorXd weightedInnovation;  ///< S^-1 z
    Eigen::MatrixXd inverseS;            ///< S^-1
};

/// Appends the record of any update of an N-state filter, on its running states. A row that is
/// zero on them (ZARU in the 9-state filter) is left out: the gain's rows for the running states
/// are zero in its column, so it changes nothing the backward pass carries. Nothing is appended
/// when no row is left. Returns whether a row left in measures position (the backward pass then
/// carries position).
bool append(Records& records, int runningStates, const GeneralUpdate& update);

/// K of the record that starts at record (15 x rows, zero in the states the filter does not
/// run): for tests.
Eigen::MatrixXd gainOf(const double* record, int runningStates);

}  // namespace update_record

}  // namespace footpath
