#pragma once

#include "comm/device/connection_settings.h"
#include "model/result.h"

#include <QByteArray>
#include <QString>

#include <memory>

namespace cambench::comm {

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
