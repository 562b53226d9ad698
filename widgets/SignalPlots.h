#pragma once

#include "SessionView.h"
#include "Recording.h"
#include "Result.h"

#include <QWidget>

#include <array>
#include <memory>
#include <vector>

class QAction;
class QCheckBox;
class QCPLegend;
class QCPMarginGroup;
class QCPAxisRect;
class QCPGraph;
class QCPItemStraightLine;
class QCPRange;
class QCustomPlot;
class QMouseEvent;
class QPainter;
class QToolBar;

namespace footpath {

class DeferredReplot;

class LegendStrip;
class LinkedTimeRows;
class PlotInteraction;
class TimeBands;
class WarningOverlay;

/// The recording's raw signals in stacked rows that share one time axis: acceleration, angular
/// rate, magnetic field and pressure/barometric height (the last two only when recorded). Stance
/// phases of a result are shaded behind every row, and its plausibility warnings in red with a
/// lane of labelled bars above the rows; a time cursor runs through all rows.
///
/// Navigation: mouse wheel zooms and dragging pans the time axis only; +/- zoom, Left/Right pan,
/// Home shows the whole recording; a click places the time cursor and emits timeCursorMoved.
/// The widget knows nothing of the session: MainWindow wires the setters and signals. Setters
/// schedule one replot for the next event-loop pass, so several in a row draw once.
class SignalPlots : public QWidget, public SessionView {
    Q_OBJECT
public:
    enum class Channel { AccX, AccY, AccZ, AccNorm, GyrX, GyrY, GyrZ, MagX, MagY, MagZ, Pressure, Height };
    Q_ENUM(Channel)
    /// One stacked axis rect each; a row is shown when the recording has its data and at least
    /// one of its channels is switched on.
    enum class Row { Acceleration, AngularRate, MagneticField, Pressure, Height };
    Q_ENUM(Row)
    static constexpr int kChannelCount = 12;
    static constexpr int kRowCount = 5;

    explicit SignalPlots(QWidget* parent = nullptr);
    ~SignalPlots() override;
    void showRecording(const AnalysisSession& session) override;
    void showEstimate(const AnalysisSession& session) override;
    void showTimeCursor(double time_s) override { setTimeCursor(time_s); }

    /// Plots every sample; the previous result's shading is dropped (it belonged to the old recording).
    void setRecording(std::shared_ptr<const Recording> recording);
    /// Shades result->flags.stance and the spans of result->warnings; nullptr removes the shading.
    void setResult(std::shared_ptr<const Result> result);
    void setTimeCursor(double time_s);
    /// Shows [from_s, to_s] on the shared time axis; emits timeRangeChanged if that is a change.
    void setTimeRange(double from_s, double to_s);
    void setChannelVisible(Channel channel, bool visible);
    /// Time range of the whole recording (what Home shows).
    void showAll();

    bool isChannelVisible(Channel channel) const;
    bool isRowShown(Row row) const;
    double timeCursor() const { return timeCursor_s_; }
    QCPRange timeRange() const;

    /// For the PDF report (QCustomPlot::toPainter, savePdf) and for tests.
    QCustomPlot* plot() const { return plot_; }
    QCPAxisRect* axisRect(Row row) const;
    QCPGraph* graph(Channel channel) const;
    /// The result's heel strikes or toe offs, marked on the angular-rate row's zero line (for
    /// tests); the other kinds are not drawn.
    QCPGraph* gaitEventMarks(GaitEventKind kind) const;
    /// The legend above the rows: the shown channels (x, y, z once for all rows) and the stance.
    QCPLegend* legend() const;
    /// Whether time_s lies in a shaded stance span (the span from a stance's first sample to the
    /// sample after its last).
    bool isStanceShaded(double time_s) const;
    /// The result's plausibility warnings as bands, labels and tool tips.
    const WarningOverlay& warningOverlay() const { return *warnings_; }
    QCPItemStraightLine* cursorLine(Row row) const;
    /// The lane of labelled warning bars above the rows; in the layout while there are warnings.
    QCPAxisRect* warningLane() const { return warningLane_.rect; }
    /// Hover readout, marker, Y zoom, context menu and export.
    PlotInteraction* interaction() const { return interaction_; }
    /// Draws the plots (without the channel toolbar) into target as vector commands, so a PDF
    /// painter keeps them sharp.
    void renderTo(QPainter& painter, const QRect& target);

signals:
    /// The user clicked in a plot at this time.
    void timeCursorMoved(double time_s);
    /// The visible time range changed (user zoom or pan, Home, or setTimeRange).
    void timeRangeChanged(double from_s, double to_s);

protected:
    void keyPressEvent(QKeyEvent* event) override;

private:
    struct RowParts {
        QCPAxisRect* rect = nullptr;
        TimeBands* stance = nullptr;
        QCPItemStraightLine* cursor = nullptr;
        QAction* group = nullptr;  ///< the toolbar's group (label, check boxes): hidden without data
    };

    void createRows();
    void createWarningLane(QCPMarginGroup* alignedMargins);
    void createGraphs();
    void createToolBar();
    void wireInteractions();
    void plotSignals(const Recording& recording);
    void plotStanceShading();
    void createGaitEventMarks();
    void plotGaitEvents();
    void rescaleValueAxes();
    void arrangeRows();
    void keepRowsReadable();
    bool rowHasData(Row row) const;
    std::vector<RowParts*> allRows();  ///< the warning lane and the signal rows

    QCustomPlot* plot_;
    DeferredReplot* replot_;  ///< one replot per event-loop pass for the setters, none while hidden
    QToolBar* toolBar_;
    std::array<RowParts, kRowCount> rows_;
    std::array<QCPGraph*, kChannelCount> graphs_{};
    LegendStrip* legend_ = nullptr;  ///< one for all rows, above them
    QCPGraph* stanceLegendEntry_ = nullptr;  ///< draws nothing; gives the bands a legend entry
    QCPGraph* heelStrikes_ = nullptr;  ///< on the angular-rate row, where the events are read
    QCPGraph* toeOffs_ = nullptr;
    RowParts warningLane_;  ///< above the rows while the result has warnings
    WarningOverlay* warnings_ = nullptr;
    std::array<QCheckBox*, kChannelCount> channelBoxes_{};
    std::array<bool, kChannelCount> channelVisible_{};
    std::shared_ptr<const Recording> recording_;
    std::shared_ptr<const Result> result_;
    double timeCursor_s_ = 0.0;
    bool cursorPlaced_ = false;  ///< the cursor stays hidden until someone places it
    LinkedTimeRows* timeRows_ = nullptr;  ///< made with the rows
    PlotInteraction* interaction_ = nullptr;
};

}  // namespace footpath
