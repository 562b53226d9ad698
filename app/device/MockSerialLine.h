#pragma once

#include "DevicePort.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <functional>
#include <memory>

namespace footpath {

/// An in-memory serial line for tests: the ports its factory() makes talk to it instead of to
/// hardware. A test scripts the device side with a responder (called for every write, in the
/// port's thread), pushes bytes with feedReceived() and breaks the line with injectFailure();
/// both are safe from any thread and reach the port through its event loop, as real bytes do.
class MockSerialLine {
public:
    /// Gets what the host wrote, returns what the device answers (may be empty).
    using Responder = std::function<QByteArray(const QByteArray& written)>;

    MockSerialLine();

    DevicePortFactory factory() const;
    void setResponder(Responder responder);
    /// The next open() fails with this text (empty: opens succeed).
    void setOpenError(const QString& text);

    void feedReceived(const QByteArray& bytes);
    void injectFailure(DevicePort::Failure kind, const QString& message);

    QByteArray written() const;       ///< everything the host wrote so far
    QList<quint32> baudRates() const;  ///< each rate the host opened the line with or switched to
    bool isOpen() const;

    struct Shared;  ///< state shared with the ports (the line outlives none of them)

private:
    std::shared_ptr<Shared> shared_;
};

}  // namespace footpath
