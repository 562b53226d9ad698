#include "ComparisonTable.h"

#include "PlotInteraction.h"

#include <QCoreApplication>
#include <QStringList>

#include <cmath>

namespace footpath {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("footpath::ComparisonTable", text);
}

bool anyValue(const std::vector<ComparisonRow>& rows, double ComparisonRow::*member)
{
    for (const ComparisonRow& row : rows)
        if (!std::isnan(row.*member) && comparisonRowProblem(row).isEmpty())
            return true;
    return false;
}

/// A figure that is only meaningful when the row's run gave a result.
std::function<QString(const ComparisonRow&)> figure(double ComparisonRow::*member, int decimals)
{
    return [member, decimals](const ComparisonRow& row) {
        return comparisonRowProblem(row).isEmpty() ? formatFigure(row.*member, decimals) : QStringLiteral("\u2013");
    };
}

}  // namespace

QString methodSetText(const std::string& setName)
{
    return QString::fromStdString(footpath::methodSetLabel(setName));
}

QColor comparisonColour(std::size_t index)
{
    // Tableau's ten, without its blue (the main path's colour) and its grey (the reference's).
    static const QColor colours[] = {QColor(255, 127, 14), QColor(44, 160, 44), QColor(214, 39, 40),
                                     QColor(148, 103, 189), QColor(140, 86, 75), QColor(227, 119, 194),
                                     QColor(188, 189, 34), QColor(23, 190, 207), QColor(0, 0, 0)};
    constexpr std::size_t count = sizeof(colours) / sizeof(colours[0]);
    return colours[index % count];
}

QString comparisonRowProblem(const ComparisonRow& row)
{
    if (!row.output.error.empty())
        return tr("failed: %1").arg(QString::fromStdString(row.output.error));
    if (row.output.result.cancelled)
        return tr("cancelled");
    if (row.output.result.position_m.empty())
        return tr("no estimate");
    return {};
}

std::vector<ComparisonColumn> comparisonColumns(const std::vector<ComparisonRow>& rows)
{
    std::vector<ComparisonColumn> columns;
    columns.push_back({tr("Method set"), {}, [](const ComparisonRow& row) { return methodSetText(row.set.name); }});
    columns.push_back({tr("End to start\n(m)"), "end_to_start_m", figure(&ComparisonRow::endToStart_m, 2)});
    columns.push_back({tr("End to start\n(%)"), "end_to_start_pct", figure(&ComparisonRow::endToStartPct, 2)});
    columns.push_back({tr("Path length\n(m)"), {}, figure(&ComparisonRow::pathLength_m, 2)});
    columns.push_back({tr("Height change\n(m)"), {}, figure(&ComparisonRow::heightChange_m, 2)});
    if (anyValue(rows, &ComparisonRow::armse2d_m))
        columns.push_back({tr("ARMSE 2D\n(m)"), "armse_2d_m", figure(&ComparisonRow::armse2d_m, 3)});
    if (anyValue(rows, &ComparisonRow::stanceF1))
        columns.push_back({tr("Stance F1"), "stance_f1", figure(&ComparisonRow::stanceF1, 3)});
    columns.push_back({tr("Steps"), {}, [](const ComparisonRow& row) {
                           return comparisonRowProblem(row).isEmpty() ? QString::number(row.output.result.summary.steps)
                                                                      : QStringLiteral("\u2013");
                       }});
    columns.push_back({tr("Warnings"), {}, [](const ComparisonRow& row) {
                           const QString problem = comparisonRowProblem(row);
                           return problem.isEmpty() ? QString::number(row.output.result.warnings.size()) : problem;
                       }});
    return columns;
}

int bestRowOfColumn(const std::vector<ComparisonRow>& rows, const ComparisonColumn& column)
{
    return column.bestKey.empty() ? -1 : bestComparisonRow(rows, column.bestKey);
}

QString bestMarker()
{
    return QStringLiteral(" \u2605");
}

}  // namespace footpath
