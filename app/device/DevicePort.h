#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

#include <functional>
#include <memory>

namespace footpath {

/// The byte pipe a DeviceSession talks through: a real serial port, or an in-memory line that
/// tests script (MockSerialLine). Lives in the session's worker thread.
class DevicePort : public QObject {
    Q_OBJECT
public:
    enum class Failure {
        Vanished,  ///< the port went away (USB unplugged, emulator quit)
        Io,        ///< reading or writing failed
    };
    Q_ENUM(Failure)

    using QObject::QObject;

    /// 8 data bits, no parity, 1 stop bit, no flow control (docs/xbus.md §5).
    virtual bool open(const QString& portName, quint32 baud) = 0;
    virtual void close() = 0;
    virtual bool setBaudRate(quint32 baud) = 0;
    /// False if not every byte could be handed to the port.
    virtual bool write(const QByteArray& data) = 0;
    virtual QByteArray readAll() = 0;
    /// What went wrong last, in the system's words.
    virtual QString errorString() const = 0;

signals:
    void readyRead();
    /// The open port broke; the session ends.
    void failed(footpath::DevicePort::Failure kind, const QString& message);
};

/// Makes a port; called in the worker thread, so the port belongs to it.
using DevicePortFactory = std::function<std::unique_ptr<DevicePort>()>;

/// Ports backed by QSerialPort.
DevicePortFactory serialDevicePortFactory();

}  // namespace footpath
