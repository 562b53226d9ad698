#include "OtherFootSession.h"

#include "AnalysisSession.h"
#include "PipelineRunner.h"
#include "RecordingLoader.h"

#include <QFileInfo>

namespace footpath {

OtherFootSession::OtherFootSession(AnalysisSession& session, QObject* parent)
    : QObject(parent), session_(session), loader_(new RecordingLoader(this)), runner_(new PipelineRunner(this))
{
    connect(loader_, &RecordingLoader::loaded, this,
            [this](const QString& path, const std::shared_ptr<const ImportResult>& read) {
                read_ = read;
                recording_ = std::shared_ptr<const Recording>(read, &read->recording);  // shared, not copied
                emit readDone(path);
                estimate();
            });
    connect(loader_, &RecordingLoader::failed, this, [this](const QString& path, const QString& message) {
        const QString problem = tr("%1 (the right foot): %2").arg(QFileInfo(path).fileName(), message);
        clear();
        emit failed(problem);
    });
    connect(runner_, &PipelineRunner::finished, this, [this](const std::shared_ptr<const Result>& result) {
        result_ = result;
        estimating_ = false;
        combine();
    });
    connect(runner_, &PipelineRunner::failed, this, [this](const QString& message) {
        estimating_ = false;
        emit failed(tr("The right foot's estimate failed: %1").arg(message));
        combine();  // the left's new result may have waited for this one
    });
    connect(&session_, &AnalysisSession::parametersChanged, this, &OtherFootSession::estimate);
    connect(&session_, &AnalysisSession::resultChanged, this, &OtherFootSession::combine);
    connect(&session_, &AnalysisSession::estimateFailed, this, &OtherFootSession::combine);  // likewise
}

OtherFootSession::~OtherFootSession() = default;

void OtherFootSession::load(const QString& path, const QStringList& notes)
{
    clear();
    path_ = path;
    notes_ = notes;
    loader_->load(path, ImportOptions());
    emit changed();
}

void OtherFootSession::clear()
{
    const bool wasActive = isActive();
    loader_->cancel();
    runner_->cancel();
    estimating_ = false;
    path_.clear();
    notes_.clear();
    read_.reset();
    recording_.reset();
    result_.reset();
    bothFeet_.reset();
    alignedPath_.clear();
    if (wasActive)
        emit changed();
}

void OtherFootSession::estimate()
{
    if (!recording_)
        return;
    // The right foot's previous result stays until the new one is there (as the left's does).
    runner_->run(recording_, session_.parameters());
    estimating_ = true;
}

void OtherFootSession::combine()
{
    const std::shared_ptr<const Result> left = session_.result();
    if (!isActive())
        return;
    // After a parameter change both feet are estimated again, and each result calls this. The
    // first to arrive would be paired with the other foot's estimate for the old parameters:
    // only the second combines (the figures stay those of the old pair until then).
    if (left && result_ && (estimating_ || session_.isEstimating()))
        return;
    if (left && result_) {
        bothFeet_ = analyseBilateralGait(*left, *result_);
        // How the sides were decided travels with the figures (summary, report).
        for (const QString& note : notes_)
            bothFeet_->warnings.insert(bothFeet_->warnings.begin(), note.toStdString());
        alignedPath_ = otherFootPathAligned(*left, *result_);
    } else {
        bothFeet_.reset();
        alignedPath_.clear();
    }
    emit changed();
}

}  // namespace footpath
