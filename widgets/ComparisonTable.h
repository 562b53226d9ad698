#pragma once

#include "nav/MethodSets.h"

#include <QColor>
#include <QString>

#include <functional>
#include <vector>

namespace footpath {

/// methodSetLabel (core) as a QString: how the panel, the legends and the report name a set.
QString methodSetText(const std::string& setName);

/// A colour per set, distinct from each other and from the main path's blue.
QColor comparisonColour(std::size_t index);

/// One column of the comparison table, shared by the panel and the PDF report so both show the
/// same figures the same way.
struct ComparisonColumn {
    QString title;  ///< the unit on a second line, so the columns stay narrow
    /// bestComparisonRow's column name, or empty when the column has no "best".
    std::string bestKey;
    std::function<QString(const ComparisonRow&)> text;
};

/// The columns for these rows: ARMSE 2D and stance F1 only when some row has a value (the
/// recording has the reference they need).
std::vector<ComparisonColumn> comparisonColumns(const std::vector<ComparisonRow>& rows);

/// Why a row has no figures ("failed: ...", "cancelled"), or empty when it has them.
QString comparisonRowProblem(const ComparisonRow& row);

/// Index of the best row of a column, -1 when the column has no best or no row has a value.
int bestRowOfColumn(const std::vector<ComparisonRow>& rows, const ComparisonColumn& column);

/// Appended to a best value in the panel and the report.
QString bestMarker();

}  // namespace footpath
