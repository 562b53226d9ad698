#include "MockSerialLine.h"

#include <QMutex>
#include <QMutexLocker>
#include <QPointer>

namespace footpath {

class MockDevicePort;

struct MockSerialLine::Shared {
    mutable QMutex mutex;
    Responder responder;
    QString openError;
    QByteArray written;
    QList<quint32> baudRates;
    MockDevicePort* port = nullptr;  ///< the open port, cleared by the port itself under the mutex
};

/// The port side of the line; lives in the thread that made it.
class MockDevicePort : public DevicePort {
public:
    explicit MockDevicePort(std::shared_ptr<MockSerialLine::Shared> shared) : shared_(std::move(shared)) {}
    ~MockDevicePort() override { detach(); }

    bool open(const QString&, quint32 baud) override
    {
        QMutexLocker lock(&shared_->mutex);
        if (!shared_->openError.isEmpty()) {
            error_ = shared_->openError;
            return false;
        }
        shared_->port = this;
        shared_->baudRates.append(baud);
        open_ = true;
        return true;
    }
    void close() override
    {
        detach();
        open_ = false;
    }
    bool setBaudRate(quint32 baud) override
    {
        QMutexLocker lock(&shared_->mutex);
        shared_->baudRates.append(baud);
        return open_;
    }
    bool write(const QByteArray& data) override
    {
        if (!open_ || broken_)
            return false;
        MockSerialLine::Responder responder;
        {
            QMutexLocker lock(&shared_->mutex);
            shared_->written.append(data);
            responder = shared_->responder;
        }
        if (responder)
            post(responder(data));
        return true;
    }
    QByteArray readAll() override { return std::exchange(received_, {}); }
    QString errorString() const override { return error_; }

    /// Queued so that answers arrive after write() returned, as on a real line.
    void post(const QByteArray& bytes)
    {
        if (bytes.isEmpty())
            return;
        QMetaObject::invokeMethod(this, [this, bytes] { deliver(bytes); }, Qt::QueuedConnection);
    }
    void postFailure(Failure kind, const QString& message)
    {
        QMetaObject::invokeMethod(
            this,
            [this, kind, message] {
                broken_ = true;
                error_ = message;
                if (open_)
                    emit failed(kind, message);
            },
            Qt::QueuedConnection);
    }

private:
    void deliver(const QByteArray& bytes)
    {
        if (!open_ || broken_)
            return;
        received_.append(bytes);
        emit readyRead();
    }
    void detach()
    {
        QMutexLocker lock(&shared_->mutex);
        if (shared_->port == this)
            shared_->port = nullptr;
    }

    std::shared_ptr<MockSerialLine::Shared> shared_;
    QByteArray received_;
    QString error_;
    bool open_ = false;
    bool broken_ = false;
};

MockSerialLine::MockSerialLine() : shared_(std::make_shared<Shared>()) {}

DevicePortFactory MockSerialLine::factory() const
{
    return [shared = shared_] { return std::make_unique<MockDevicePort>(shared); };
}

void MockSerialLine::setResponder(Responder responder)
{
    QMutexLocker lock(&shared_->mutex);
    shared_->responder = std::move(responder);
}

void MockSerialLine::setOpenError(const QString& text)
{
    QMutexLocker lock(&shared_->mutex);
    shared_->openError = text;
}

void MockSerialLine::feedReceived(const QByteArray& bytes)
{
    // Posting under the mutex: the port cannot be destroyed in between (its destructor takes it).
    QMutexLocker lock(&shared_->mutex);
    if (shared_->port != nullptr)
        shared_->port->post(bytes);
}

void MockSerialLine::injectFailure(DevicePort::Failure kind, const QString& message)
{
    QMutexLocker lock(&shared_->mutex);
    if (shared_->port != nullptr)
        shared_->port->postFailure(kind, message);
}

QByteArray MockSerialLine::written() const
{
    QMutexLocker lock(&shared_->mutex);
    return shared_->written;
}

QList<quint32> MockSerialLine::baudRates() const
{
    QMutexLocker lock(&shared_->mutex);
    return shared_->baudRates;
}

bool MockSerialLine::isOpen() const
{
    QMutexLocker lock(&shared_->mutex);
    return shared_->port != nullptr;
}

}  // namespace footpath
