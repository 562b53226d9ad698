#pragma once

#include <QList>
#include <QString>

#include <optional>

namespace footpath {

/// A serial port as the port list of the live panel shows it.
struct SerialPortDescription {
    QString portName;        ///< what DeviceSession opens: "/dev/ttyUSB0", "COM3"
    QString description;     ///< the driver's or USB product's text
    QString manufacturer;
    QString serialNumber;
    std::optional<quint16> usbVendorId;
    std::optional<quint16> usbProductId;

    /// Xsens' own USB vendor id (0x2639): an MTi with a native USB interface or Xsens cable.
    bool isXsens() const;
    /// "/dev/ttyUSB0 - MTi USB Converter (Xsens, USB 2639:0017)".
    QString displayText() const;
};

/// The serial ports of this computer, Xsens devices first. Pseudo-terminals (the emulator's)
/// are not listed by the system; the panel lets the user type such a path.
QList<SerialPortDescription> availableSerialPorts();

/// Whether `portName` can be opened again: a device node or link that exists (a replugged USB
/// adapter, the emulator's pseudo-terminal), or a port the system lists (Windows' COM names).
bool serialPortPresent(const QString& portName);

}  // namespace footpath
