#pragma once

#include "io/Import.h"

#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include <atomic>
#include <memory>

namespace footpath {

/// Opens a recording off the GUI thread with progress and cancel. Only the newest request reports.
class RecordingLoader : public QObject {
    Q_OBJECT
public:
    explicit RecordingLoader(QObject* parent = nullptr);
    ~RecordingLoader() override;

    void load(const QString& path, const ImportOptions& options);
    void cancel();
    bool isLoading() const;
    /// True when a newer read was asked for after the one now reporting (or last reported): a
    /// handler of failed() can tell that another handler already opened the file again.
    bool superseded() const { return requests_ != reported_; }

signals:
    void progress(double fraction);  ///< emitted from the worker; delivered queued
    void loaded(const QString& path, std::shared_ptr<const footpath::ImportResult> result);
    void failed(const QString& path, const QString& message, const footpath::ImportOptions& options);
    void cancelled(const QString& path);

private:
    void onFinished();

    QFutureWatcher<std::shared_ptr<const ImportResult>> watcher_;
    std::shared_ptr<std::atomic_bool> cancel_;
    QString path_;
    ImportOptions options_;
    quint64 requests_ = 0;  ///< load() calls so far
    quint64 reported_ = 0;  ///< the request whose result was last reported
};

}  // namespace footpath
