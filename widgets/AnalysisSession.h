#pragma once

#include "Recording.h"
#include "Result.h"
#include "io/Import.h"
#include "metrics/ResultEvaluation.h"
#include "nav/Parameters.h"

#include <QObject>
#include <QString>

#include <memory>

class QUndoStack;

namespace footpath {

class PipelineRunner;

/// Owns what the workspace shows: the current recording, the parameters, the latest result and the
/// time cursor. Views never talk to each other; they listen to this object (wired by MainWindow)
/// and report user actions back to it. Parameter changes are undoable and re-run the estimate in
/// the background at once; a newer change cancels an older run.
class AnalysisSession : public QObject {
    Q_OBJECT
public:
    explicit AnalysisSession(QObject* parent = nullptr);
    ~AnalysisSession() override;

    std::shared_ptr<const Recording> recording() const { return recording_; }
    const RecordingInfo& recordingInfo() const { return info_; }
    QString recordingPath() const { return path_; }
    std::shared_ptr<const Result> result() const { return result_; }
    /// The figures of result(), evaluated once against the recording (null with no result).
    std::shared_ptr<const ResultEvaluation> evaluation() const { return evaluation_; }
    /// The parameters result() was estimated with: parameters() runs ahead of it while a newer
    /// estimate is on its way, and a view that draws the result's threshold takes these.
    const Parameters& resultParameters() const { return resultParams_; }
    const Parameters& parameters() const { return params_; }
    double timeCursor() const { return timeCursor_; }
    QUndoStack* undoStack() const { return undoStack_; }
    bool isEstimating() const;

    /// Replaces the recording (the parameters stay) and starts an estimate.
    void setRecording(std::shared_ptr<const Recording> recording, const RecordingInfo& info, const QString& path);
    /// An undoable change of one parameter (flags as 0/1, choices as their index); rapid changes of the same field (a slider being
    /// dragged) merge into one undo step.
    void setParameter(const QString& name, double value);
    /// An undoable change of the whole set (preset loaded, reset to defaults).
    void setParameters(const Parameters& params, const QString& description);
    void setTimeCursor(double time_s);

signals:
    void recordingChanged();
    void parametersChanged();
    void resultChanged();
    void estimatingChanged(bool running);
    void estimateFailed(const QString& message);
    void timeCursorChanged(double time_s);

private:
    friend class ParameterChange;
    void applyParameters(const Parameters& params);  ///< no undo entry; used by the undo commands
    void estimate();
    void stopEstimating();
    void onResult(const std::shared_ptr<const Result>& result, const std::shared_ptr<const ResultEvaluation>& evaluation);

    std::shared_ptr<const Recording> recording_;
    RecordingInfo info_;
    QString path_;
    Parameters params_;
    std::shared_ptr<const Result> result_;
    std::shared_ptr<const ResultEvaluation> evaluation_;
    Parameters resultParams_;   ///< what result_ was estimated with
    Parameters runningParams_;  ///< what the estimate on its way was started with
    double timeCursor_ = 0.0;
    QUndoStack* undoStack_;
    PipelineRunner* runner_;
    bool estimating_ = false;
};

}  // namespace footpath
