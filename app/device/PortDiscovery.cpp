#include "PortDiscovery.h"

#include <QFileInfo>
#include <QSerialPortInfo>
#include <QStringList>

#include <algorithm>

namespace footpath {

namespace {

constexpr quint16 kXsensUsbVendorId = 0x2639;

QString hex4(quint16 value)
{
    return QStringLiteral("%1").arg(value, 4, 16, QLatin1Char('0'));
}

SerialPortDescription describe(const QSerialPortInfo& info)
{
    SerialPortDescription port;
    port.portName = info.systemLocation();
    port.description = info.description();
    port.manufacturer = info.manufacturer();
    port.serialNumber = info.serialNumber();
    if (info.hasVendorIdentifier())
        port.usbVendorId = info.vendorIdentifier();
    if (info.hasProductIdentifier())
        port.usbProductId = info.productIdentifier();
    return port;
}

}  // namespace

bool SerialPortDescription::isXsens() const
{
    return usbVendorId == kXsensUsbVendorId;
}

QString SerialPortDescription::displayText() const
{
    QStringList details;
    if (!manufacturer.isEmpty())
        details << manufacturer;
    if (usbVendorId && usbProductId)
        details << QStringLiteral("USB %1:%2").arg(hex4(*usbVendorId), hex4(*usbProductId));
    QString text = portName;
    if (!description.isEmpty())
        text += QStringLiteral(" - ") + description;
    if (!details.isEmpty())
        text += QStringLiteral(" (") + details.join(QStringLiteral(", ")) + QLatin1Char(')');
    return text;
}

QList<SerialPortDescription> availableSerialPorts()
{
    QList<SerialPortDescription> ports;
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts())
        ports.append(describe(info));
    std::stable_sort(ports.begin(), ports.end(), [](const SerialPortDescription& a, const SerialPortDescription& b) {
        return a.isXsens() && !b.isXsens();
    });
    return ports;
}

bool serialPortPresent(const QString& portName)
{
    if (portName.isEmpty())
        return false;
    if (QFileInfo::exists(portName))  // follows links: a dangling emulator link is not present
        return true;
    const QList<QSerialPortInfo> ports = QSerialPortInfo::availablePorts();
    return std::any_of(ports.begin(), ports.end(), [&](const QSerialPortInfo& info) {
        return info.portName() == portName || info.systemLocation() == portName;
    });
}

}  // namespace footpath
