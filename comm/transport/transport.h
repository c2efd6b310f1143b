#pragma once

#include "model/result.h"

#include <QByteArray>
#include <QString>

#include <memory>

namespace cambench::comm {

// Serial line settings; every one QSerialPort offers.
struct SerialSettings {
    int baud = 9600;
    int dataBits = 8;
    char parity = 'N';       // 'N', 'E', 'O', 'S', 'M'
    int stopBits = 1;        // 1 or 2 (3 = one and a half)
    char flowControl = 'N';  // 'N' none, 'H' RTS/CTS, 'S' XON/XOFF
    bool dtr = true;         // failing to set DTR/RTS (pty) must not abort a connection
    bool rts = true;
};

// How to reach the device. `port` is a device path or name (/dev/ttyUSB0,
// COM3, any pty path), "tcp://host:port" (serial device servers) or "sim".
struct ConnectionSettings {
    QString port = QStringLiteral("sim");
    SerialSettings serial;
    // The protocol id the PC speaks ("standard", "3964r-n96"): a transport
    // ignores it, but a simulated device on the far side answers in it.
    QString protocol;
};

// A byte pipe to the device, used only from the worker thread, with a
// blocking API bounded by deadlines: the worker thread may wait on the line,
// the caller's thread never does. One interface for serial, TCP and the
// in-process simulator; the rest of the code does not know which.
class Transport {
public:
    virtual ~Transport() = default;

    virtual Status open() = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;

    // Queues bytes and waits until they are handed to the OS.
    virtual Status write(const QByteArray& bytes) = 0;

    // Waits up to `timeoutMs` for bytes; returns what arrived, empty on a
    // quiet line. An error means the line is gone (port removed, socket
    // closed) and the transport is closed.
    virtual Result<QByteArray> read(int timeoutMs) = 0;

    // Drops bytes already received (before a retry).
    virtual void discardInput() = 0;

    // For messages: "/dev/ttyUSB0 at 9600 8N1", "tcp://10.0.0.5:4001".
    virtual QString description() const = 0;
};

}  // namespace cambench::comm
