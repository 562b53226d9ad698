#include "nav/UpdateRecord.h"

#include "nav/ErrorStateEkf.h"

namespace footpath::update_record {

namespace {

using E = ErrorStateEkf;

int stateOf(int runningStates, int running)
{
    return runningStates == E::kStates ? E::filterIndex<E::kStates>(running) : E::filterIndex<9>(running);
}

int runningIndexOf(int runningStates, int state)
{
    return runningStates == E::kStates ? E::runningIndex<E::kStates>(state) : E::runningIndex<9>(state);
}

bool observesPosition(const GeneralUpdate& update, int row)
{
    if (update.selectedStates.size() > 0)
        return E::isPosition(update.selectedStates(row));
    return update.h.row(row).segment<3>(E::kPos).any();  // any non-zero entry
}

}  // namespace

bool append(Records& records, int runningStates, const GeneralUpdate& update)
{
    const int n = runningStates;
    const bool selects = update.selectedStates.size() > 0;
    const auto seesRunningStates = [&](int row) {
        if (selects)
            return runningIndexOf(n, update.selectedStates(row)) >= 0;
        for (int i = 0; i < n; ++i)
            if (update.h(row, stateOf(n, i)) != 0.0)
                return true;
        return false;
    };
    std::vector<int> kept;  // a few updates a stride take this way: the allocation does not count
    bool position = false;
    for (int row = 0; row < update.gain.cols(); ++row)
        if (seesRunningStates(row)) {
            kept.push_back(row);
            position = position || observesPosition(update, row);
        }
    if (kept.empty() || kept.size() > static_cast<std::size_t>(kMaxRows))
        return false;
    const int m = static_cast<int>(kept.size());
    const std::size_t size = length(n, m, selects);
    const std::size_t begin = records.size();
    records.resize(begin + size);
    double* out = records.data() + begin;
    *out++ = static_cast<double>(m);
    *out++ = selects ? 1.0 : 0.0;
    for (const int row : kept) {
        if (selects) {
            *out++ = static_cast<double>(runningIndexOf(n, update.selectedStates(row)));
            continue;
        }
        for (int i = 0; i < n; ++i)
            *out++ = update.h(row, stateOf(n, i));
    }
    for (const int row : kept)
        for (int i = 0; i < n; ++i)
            *out++ = update.gain(stateOf(n, i), row);
    for (const int row : kept)
        *out++ = update.weightedInnovation(row);
    for (const int col : kept)
        for (const int row : kept)
            *out++ = update.inverseS(row, col);
    *out = static_cast<double>(size);
    return position;
}

Eigen::MatrixXd gainOf(const double* record, int runningStates)
{
    const int n = runningStates;
    const int rows = static_cast<int>(record[0]);
    const bool selects = record[1] != 0.0;
    const double* gain = record + 2 + (selects ? rows : rows * n);
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(E::kStates, rows);
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < n; ++i)
            k(stateOf(n, i), j) = gain[j * n + i];
    return k;
}

}  // namespace footpath::update_record
