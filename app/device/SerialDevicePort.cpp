#include "SerialDevicePort.h"

namespace footpath {

DevicePortFactory serialDevicePortFactory()
{
    return [] { return std::make_unique<SerialDevicePort>(); };
}

SerialDevicePort::SerialDevicePort(QObject* parent) : DevicePort(parent), port_(this)
{
    connect(&port_, &QSerialPort::readyRead, this, &DevicePort::readyRead);
    connect(&port_, &QSerialPort::errorOccurred, this, &SerialDevicePort::onErrorOccurred);
}

bool SerialDevicePort::open(const QString& portName, quint32 baud)
{
    failureReported_ = false;
    port_.setPortName(portName);
    port_.setDataBits(QSerialPort::Data8);
    port_.setParity(QSerialPort::NoParity);
    port_.setStopBits(QSerialPort::OneStop);
    port_.setFlowControl(QSerialPort::NoFlowControl);
    return port_.open(QIODevice::ReadWrite) && setBaudRate(baud);
}

void SerialDevicePort::close()
{
    if (port_.isOpen())
        port_.close();
}

bool SerialDevicePort::setBaudRate(quint32 baud)
{
    return port_.setBaudRate(static_cast<qint32>(baud));
}

bool SerialDevicePort::write(const QByteArray& data)
{
    return port_.isOpen() && port_.write(data) == data.size();
}

QByteArray SerialDevicePort::readAll()
{
    return port_.readAll();
}

QString SerialDevicePort::errorString() const
{
    return port_.errorString();
}

void SerialDevicePort::onErrorOccurred(QSerialPort::SerialPortError error)
{
    // Only errors of an open port end a session; open() reports its own through its result.
    // A vanished port keeps signalling: report it once.
    if (!port_.isOpen() || failureReported_)
        return;
    // A tty whose other end hung up reads end-of-file, which QSerialPort reports as ReadError
    // rather than ResourceError: on an open port both mean the device is gone.
    if (error == QSerialPort::ResourceError || error == QSerialPort::ReadError) {
        failureReported_ = true;
        emit failed(Failure::Vanished, port_.errorString());
    } else if (error == QSerialPort::WriteError) {
        failureReported_ = true;
        emit failed(Failure::Io, port_.errorString());
    }
}

}  // namespace footpath
