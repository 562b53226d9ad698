#include "DeviceSession.h"

#include "DeviceWorker.h"

namespace footpath {

namespace {

void registerMetaTypes()
{
    qRegisterMetaType<footpath::DeviceInfo>();
    qRegisterMetaType<footpath::DeviceCounters>();
    qRegisterMetaType<footpath::SessionSettings>();
    qRegisterMetaType<footpath::RecordingPaths>();
    qRegisterMetaType<footpath::SessionEnd>();
    qRegisterMetaType<footpath::SessionState>();
}

}  // namespace

DeviceSession::DeviceSession(DevicePortFactory factory, QObject* parent) : QObject(parent)
{
    registerMetaTypes();
    worker_ = new DeviceWorker(std::move(factory), queue_);
    worker_->moveToThread(&thread_);
    connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
    wireWorker();
    thread_.setObjectName(QStringLiteral("DeviceSession"));
    thread_.start();
}

DeviceSession::~DeviceSession()
{
    DeviceWorker* worker = worker_;
    QMetaObject::invokeMethod(worker, [worker] { worker->shutdown(); }, Qt::BlockingQueuedConnection);
    thread_.quit();
    thread_.wait();
}

void DeviceSession::wireWorker()
{
    // Queued: the worker's signals come from its thread and are handled in this object's.
    connect(worker_, &DeviceWorker::stateChanged, this, [this](SessionState state) {
        state_ = state;
        emit stateChanged(state);
    });
    connect(worker_, &DeviceWorker::deviceIdentified, this, [this](const DeviceInfo& info) {
        info_ = info;
        emit deviceIdentified(info);
    });
    connect(worker_, &DeviceWorker::countersChanged, this, [this](const DeviceCounters& counters) {
        counters_ = counters;
        emit countersChanged(counters);
    });
    connect(worker_, &DeviceWorker::progress, this, &DeviceSession::progress);
    connect(worker_, &DeviceWorker::samplesQueued, this, &DeviceSession::samplesAvailable);
    connect(worker_, &DeviceWorker::warning, this, &DeviceSession::warning);
    connect(worker_, &DeviceWorker::recordingStarted, this, &DeviceSession::recordingStarted);
    connect(worker_, &DeviceWorker::recordingStopped, this, &DeviceSession::recordingStopped);
    connect(worker_, &DeviceWorker::ended, this, &DeviceSession::ended);
}

void DeviceSession::start(const SessionSettings& settings)
{
    DeviceWorker* worker = worker_;
    QMetaObject::invokeMethod(worker, [worker, settings] { worker->start(settings); }, Qt::QueuedConnection);
}

void DeviceSession::stop()
{
    DeviceWorker* worker = worker_;
    QMetaObject::invokeMethod(worker, [worker] { worker->stop(); }, Qt::QueuedConnection);
}

void DeviceSession::startRecording(const RecordingPaths& paths)
{
    DeviceWorker* worker = worker_;
    QMetaObject::invokeMethod(worker, [worker, paths] { worker->startRecording(paths); }, Qt::QueuedConnection);
}

void DeviceSession::stopRecording()
{
    DeviceWorker* worker = worker_;
    QMetaObject::invokeMethod(worker, [worker] { worker->stopRecording(); }, Qt::QueuedConnection);
}

std::vector<LiveSample> DeviceSession::takeSamples()
{
    return queue_.takeAll();
}

}  // namespace footpath
