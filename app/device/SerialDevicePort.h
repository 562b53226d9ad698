#pragma once

#include "DevicePort.h"

#include <QSerialPort>

namespace footpath {

/// A DevicePort on a QSerialPort: COM ports, /dev/ttyUSB*, and pseudo-terminals alike.
class SerialDevicePort : public DevicePort {
    Q_OBJECT
public:
    explicit SerialDevicePort(QObject* parent = nullptr);

    bool open(const QString& portName, quint32 baud) override;
    void close() override;
    bool setBaudRate(quint32 baud) override;
    bool write(const QByteArray& data) override;
    QByteArray readAll() override;
    QString errorString() const override;

private:
    void onErrorOccurred(QSerialPort::SerialPortError error);

    QSerialPort port_;
    bool failureReported_ = false;
};

}  // namespace footpath
