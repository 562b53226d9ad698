#pragma once

#include "SessionView.h"
#include "Result.h"

#include <QWidget>

#include <array>
#include <memory>
#include <vector>

class QCPAxisRect;
class QCPGraph;
class QCPItemStraightLine;
class QCPItemText;
class QCPLegend;
class QCPRange;
class QCustomPlot;
class QPainter;

namespace footpath {

class DecimatedGraph;

class DeferredReplot;

class LegendStrip;
class LinkedTimeRows;
class PlotInteraction;
class TimeBands;

/// What the filter estimated besides the path, in stacked rows on one time axis: roll, pitch and
/// yaw, velocity, height, and the gyroscope and accelerometer bias estimates, each curve with a
/// ±1σ band from the filter's covariance (Result::errorStd). An estimator without a covariance
/// (Feliz) gets no bands and each row says so; biases that stay constant say they were not
/// estimated. Stance is shaded behind every row and a time cursor runs through all rows.
///
/// Navigation as in SignalPlots (wheel/drag on time, +/-, Left/Right, Home, click for the cursor),
/// with setTimeRange/timeRangeChanged for MainWindow to link it to the other time plots; hover
/// readout, marker, Y zoom and export come from PlotInteraction.
class StatePlots : public QWidget, public SessionView {
    Q_OBJECT
public:
    enum class Row { Attitude, Velocity, Height, GyroBias, AccBias };
    Q_ENUM(Row)
    static constexpr int kRowCount = 5;
    static constexpr int kMaxComponents = 3;

    explicit StatePlots(QWidget* parent = nullptr);
    ~StatePlots() override;
    void showEstimate(const AnalysisSession& session) override;
    void showTimeCursor(double time_s) override { setTimeCursor(time_s); }

    /// Plots the result's states; nullptr empties the rows.
    void setResult(std::shared_ptr<const Result> result);
    void setTimeCursor(double time_s);
    /// Shows [from_s, to_s]; emits timeRangeChanged if that is a change.
    void setTimeRange(double from_s, double to_s);
    /// The result's whole time span (what Home and a double-click show).
    void showAll();

    double timeCursor() const { return timeCursor_s_; }
    QCPRange timeRange() const;
    QCustomPlot* plot() const;
    QCPAxisRect* axisRect(Row row) const;
    /// The legend above the rows (x, y and z once for velocity and the biases; ±1σ with bands).
    QCPLegend* legend() const;
    /// The curve of one component (roll/pitch/yaw, x/y/z; the height row has one).
    QCPGraph* graph(Row row, int component) const;
    /// The band's lower and upper edges of one component (empty without a covariance).
    QCPGraph* bandLower(Row row, int component) const;
    QCPGraph* bandUpper(Row row, int component) const;
    /// What the row says in place of what it cannot show ("no ±1σ band: ..."); empty when all is shown.
    QString rowNote(Row row) const;
    PlotInteraction* interaction() const { return interaction_; }
    void renderTo(QPainter& painter, const QRect& target);

signals:
    void timeCursorMoved(double time_s);
    void timeRangeChanged(double from_s, double to_s);

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    struct Component {
        DecimatedGraph* curve = nullptr;
        QCPGraph* sigma = nullptr;  ///< draws nothing: σ itself, for the readout and the CSV export
        QCPGraph* lower = nullptr;
        QCPGraph* upper = nullptr;  ///< fills down to lower
    };
    struct RowParts {
        QCPAxisRect* rect = nullptr;
        TimeBands* stance = nullptr;
        QCPItemStraightLine* cursor = nullptr;
        QCPItemText* note = nullptr;
        std::array<Component, kMaxComponents> components;
        int componentCount = 0;
        bool collapsed = false;  ///< a state not estimated: a lane saying so
        double lowest = 1.0, highest = -1.0;  ///< finite values of its curves and bands; none yet
    };

    /// One row's graphs' data, built apart from the widgets (StatePlots.cpp).
    struct RowFill;

    void createRow(std::size_t r);
    /// Fills the rows from result_ if a result came since they were last filled.
    void ensureRowsPlotted() const;
    /// Every row's data from result (none when null), the components built side by side.
    static std::array<RowFill, kRowCount> fillRows(const Result* result);
    void plotRow(std::size_t r, const RowFill& fill);
    /// Fits the row's value axis to its curves and bands (the range plotRow found).
    void rescaleRow(std::size_t r);
    void showCollapsed(std::size_t r, bool collapsed);
    void refreshLegend();

    QCustomPlot* plot_;
    DeferredReplot* replot_;  ///< one replot per event-loop pass for the setters, none while hidden
    bool rowsStale_ = false;  ///< result_ changed while hidden: the rows show an older one
    std::array<RowParts, kRowCount> rows_;
    LegendStrip* legend_ = nullptr;  ///< one for all rows, above them
    QCPGraph* bandLegendEntry_ = nullptr;  ///< draws nothing; names the bands
    std::shared_ptr<const Result> result_;
    double timeCursor_s_ = 0.0;
    LinkedTimeRows* timeRows_ = nullptr;
    PlotInteraction* interaction_ = nullptr;
};

}  // namespace footpath
