#pragma once

#include <QList>
#include <QString>

namespace cambench::comm {

// A serial port the system lists, with what tells one USB adapter from the
// next: at 2 a.m. with three adapters plugged in, "FT232R USB UART (FTDI,
// S/N A10K3ZX1, 0403:6001)" is the one that was on the machine yesterday.
struct SerialPortEntry {
    QString location;  // what to open: /dev/ttyUSB0, COM3
    QString description;
    QString manufacturer;
    QString serialNumber;
    int vendorId = -1;  // -1: not a USB device (or not told)
    int productId = -1;

    // "FT232R USB UART (FTDI, S/N A10K3ZX1, 0403:6001)"; empty for a port
    // the system tells nothing about.
    QString details() const;
    // "/dev/ttyUSB0 — FT232R USB UART (FTDI, S/N A10K3ZX1, 0403:6001)".
    QString label() const;
};

// The serial ports the system lists now (pseudo-terminals and device
// servers are not among them; they are typed).
QList<SerialPortEntry> availableSerialPorts();

}  // namespace cambench::comm
