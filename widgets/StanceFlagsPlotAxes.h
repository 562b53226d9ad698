#pragma once

// Internal to StanceFlagsPlot and its rows: which axis of a row plays which part, in one place so
// every row draws against the same ones.

#include <qcustomplot.h>

#include <vector>

namespace footpath {

inline QCPAxis* timeAxis(const QCPAxisRect* rect) { return rect->axis(QCPAxis::atBottom); }
inline QCPAxis* valueAxis(const QCPAxisRect* rect) { return rect->axis(QCPAxis::atLeft); }
/// The hidden right axis spans 0..1 whatever the row shows: the cursor uses it to fill the height.
inline QCPAxis* unitAxis(const QCPAxisRect* rect) { return rect->axis(QCPAxis::atRight); }

inline QVector<double> toQVector(const std::vector<double>& values) { return QVector<double>(values.begin(), values.end()); }

}  // namespace footpath
