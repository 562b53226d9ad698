#include "RecordingLoader.h"

#include <QtConcurrent/QtConcurrentRun>

namespace footpath {

RecordingLoader::RecordingLoader(QObject* parent) : QObject(parent)
{
    connect(&watcher_, &QFutureWatcher<std::shared_ptr<const ImportResult>>::finished, this,
            &RecordingLoader::onFinished);
}

RecordingLoader::~RecordingLoader()
{
    cancel();
    watcher_.waitForFinished();
}

bool RecordingLoader::isLoading() const
{
    return watcher_.isRunning();
}

void RecordingLoader::cancel()
{
    if (cancel_)
        cancel_->store(true);
}

void RecordingLoader::load(const QString& path, const ImportOptions& options)
{
    cancel();
    watcher_.waitForFinished();  // the old read stops at its next progress check
    cancel_ = std::make_shared<std::atomic_bool>(false);
    path_ = path;
    options_ = options;
    ++requests_;
    ImportOptions withProgress = options;
    withProgress.progress = [this, cancel = cancel_](double fraction) {
        emit progress(fraction);
        return !cancel->load();
    };
    watcher_.setFuture(QtConcurrent::run([path, withProgress]() {
        return std::make_shared<const ImportResult>(importRecording(path.toStdString(), withProgress));
    }));
}

void RecordingLoader::onFinished()
{
    const std::shared_ptr<const ImportResult> result = watcher_.result();
    reported_ = requests_;
    if (cancel_ && cancel_->load()) {
        emit cancelled(path_);
        return;
    }
    if (!result->ok())
        emit failed(path_, QString::fromStdString(result->error->text()), options_);
    else
        emit loaded(path_, result);
}

}  // namespace footpath
