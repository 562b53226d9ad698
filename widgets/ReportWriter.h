#pragma once

#include "Recording.h"
#include "PathOverlay.h"
#include "Result.h"
#include "gait/BilateralGait.h"
#include "io/Import.h"
#include "metrics/ResultEvaluation.h"
#include "nav/MethodSets.h"
#include "nav/Parameters.h"

#include <QPageSize>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace footpath {

/// Everything a report shows; the window and `footpath-cli report` fill it the same way.
struct ReportContent {
    QString recordingPath;
    RecordingInfo info;
    std::shared_ptr<const Recording> recording;
    std::shared_ptr<const Result> result;
    /// result's figures as the window evaluated them; null: the report evaluates them itself.
    std::shared_ptr<const ResultEvaluation> evaluation;
    Parameters parameters;
    QString parameterSource = QStringLiteral("defaults");  ///< "defaults" or the preset's path
    QString device;                                      ///< sensor/device when known
    /// The window's method comparison, when it has one: a "Method comparison" section.
    std::vector<ComparisonRow> comparison;
    /// The parameters changed since the comparison ran (the window marks it stale): the section
    /// says so instead of passing the rows off as this report's.
    bool comparisonStale = false;
    /// Both feet open: the result is the left foot's, otherPaths holds the right's path in its
    /// frame (drawn in the path figures), bothFeet the double support and symmetry ("Both feet").
    QString pathLabel;  ///< the main path's key entry; empty: "Foot path"
    std::vector<PathOverlay> otherPaths;
    std::optional<BilateralGait> bothFeet;
};

/// Writes the PDF report: header, summary and evaluation figures, the figures as vector graphics
/// (2D and 3D trajectory, height over time, signals with stance shading, the detector's lanes for
/// a representative window, gait statistics), every parameter with the ones that differ from the
/// defaults marked, the method set, the per-step table (paged) and the import warnings. Text is
/// real text. Returns an error message, or empty on success. Needs a QApplication (the figures
/// are the workspace's own widgets, drawn offscreen).
QString writePdfReport(const ReportContent& content, const QString& path,
                       QPageSize::PageSizeId pageSize = QPageSize::A4);

/// "ZUPT+ZARU", as the method set of a results table.
QString methodSetName(const Parameters& params);

}  // namespace footpath
