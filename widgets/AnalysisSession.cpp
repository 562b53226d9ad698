#include "AnalysisSession.h"

#include "ParameterFieldValue.h"
#include "PipelineRunner.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QUndoCommand>
#include <QUndoStack>

namespace footpath {

/// One undo step: the parameter set before and after. Changes of the same single field within a
/// second of each other merge, so dragging a slider through 50 values is one step, while a value
/// typed later is a step of its own; a drag that ends where it began leaves no step.
class ParameterChange : public QUndoCommand {
public:
    ParameterChange(AnalysisSession* session, const Parameters& before, const Parameters& after, const QString& text,
                    const QString& field)
        : QUndoCommand(text), session_(session), before_(before), after_(after), field_(field),
          lastChange_ms_(QDateTime::currentMSecsSinceEpoch())
    {
    }

    void undo() override { session_->applyParameters(before_); }
    void redo() override { session_->applyParameters(after_); }
    int id() const override { return field_.isEmpty() ? -1 : 1; }
    bool mergeWith(const QUndoCommand* other) override
    {
        constexpr qint64 kGesture_ms = 1000;
        const auto* change = static_cast<const ParameterChange*>(other);
        if (change->field_ != field_ || change->lastChange_ms_ - lastChange_ms_ > kGesture_ms)
            return false;
        after_ = change->after_;
        lastChange_ms_ = change->lastChange_ms_;
        setObsolete(after_ == before_);
        return true;
    }

private:
    AnalysisSession* session_;
    Parameters before_;
    Parameters after_;
    QString field_;  ///< empty: a whole-set change, never merged
    qint64 lastChange_ms_;
};

AnalysisSession::AnalysisSession(QObject* parent)
    : QObject(parent), undoStack_(new QUndoStack(this)), runner_(new PipelineRunner(this))
{
    connect(runner_, &PipelineRunner::finished, this, &AnalysisSession::onResult);
    connect(runner_, &PipelineRunner::failed, this, [this](const QString& message) {
        estimating_ = false;
        emit estimatingChanged(false);
        emit estimateFailed(message);
    });
}

AnalysisSession::~AnalysisSession() = default;

bool AnalysisSession::isEstimating() const
{
    return estimating_;
}

void AnalysisSession::setRecording(std::shared_ptr<const Recording> recording, const RecordingInfo& info,
                                   const QString& path)
{
    recording_ = std::move(recording);
    info_ = info;
    path_ = path;
    result_.reset();
    evaluation_.reset();
    timeCursor_ = recording_ && !recording_->samples.empty() ? recording_->samples.front().time_s : 0.0;
    emit recordingChanged();
    emit resultChanged();
    emit timeCursorChanged(timeCursor_);
    estimate();
}

void AnalysisSession::setParameter(const QString& name, double value)
{
    const ParameterField* field = findParameterField(name.toStdString());
    if (!field)
        return;
    Parameters after = params_;
    setParameterValue(after, *field, value);
    if (parameterValue(after, *field) == parameterValue(params_, *field))
        return;
    // Named as the panel names it ("Undo Change C2 bound on the std of |a|"), not by its identifier.
    const QString label = QCoreApplication::translate("footpath::ParameterFields", field->label);
    undoStack_->push(new ParameterChange(this, params_, after, tr("Change %1").arg(label), name));
}

void AnalysisSession::setParameters(const Parameters& params, const QString& description)
{
    if (params == params_)
        return;
    undoStack_->push(new ParameterChange(this, params_, params, description, QString()));
}

void AnalysisSession::applyParameters(const Parameters& params)
{
    params_ = params;
    emit parametersChanged();
    estimate();
}

void AnalysisSession::setTimeCursor(double time_s)
{
    if (time_s == timeCursor_)
        return;
    timeCursor_ = time_s;
    emit timeCursorChanged(time_s);
}

void AnalysisSession::stopEstimating()
{
    runner_->cancel();  // a run for the old recording or parameters must not report afterwards
    if (estimating_) {
        estimating_ = false;
        emit estimatingChanged(false);
    }
}

void AnalysisSession::estimate()
{
    if (!recording_ || recording_->samples.size() < 2) {
        stopEstimating();
        return;
    }
    if (const std::vector<std::string> problems = params_.validate(); !problems.empty()) {
        stopEstimating();
        emit estimateFailed(QString::fromStdString(problems.front()));
        return;
    }
    runner_->run(recording_, params_);
    runningParams_ = params_;  // the runner reports the newest run only
    if (!estimating_) {
        estimating_ = true;
        emit estimatingChanged(true);
    }
}

void AnalysisSession::onResult(const std::shared_ptr<const Result>& result,
                               const std::shared_ptr<const ResultEvaluation>& evaluation)
{
    result_ = result;
    evaluation_ = evaluation;
    resultParams_ = runningParams_;
    estimating_ = runner_->isRunning();
    emit estimatingChanged(estimating_);
    emit resultChanged();
}

}  // namespace footpath
