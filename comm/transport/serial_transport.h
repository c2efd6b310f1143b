#pragma once

#include "transport.h"

#include <memory>

class QSerialPort;

namespace cambench::comm {

// A serial port (USB adapter, on-board UART or pseudo-terminal) through
// QSerialPort. The QSerialPort is created by open() and lives on the thread
// that calls open(), the worker thread; every wait is cut into slices of at
// most kSliceMs so that the caller's deadline holds.
class SerialTransport : public Transport {
public:
    static constexpr int kSliceMs = 50;

    SerialTransport(QString portName, SerialSettings settings);
    ~SerialTransport() override;

    Status open() override;
    void close() override;
    bool isOpen() const override;
    Status write(const QByteArray& bytes) override;
    Result<QByteArray> read(int timeoutMs) override;
    void discardInput() override;
    QString description() const override;

private:
    // Turns a port error into a message, closes the port and remembers why.
    Error lose(const QString& action);
    Error notOpenError() const;
    int writeTimeoutMs(qint64 bytes) const;
    Status writeRaw(const QByteArray& bytes);
    // SerialSettings::inBandBreaks on a real port: PARMRK on the input,
    // FF 00 00 written as a real break.
    void enableBreakMarks();
    Status writeWithBreaks(const QByteArray& bytes);
    bool isPseudoTerminal() const;
    // The port's error means the line is gone (clears one that does not).
    bool lineGone();

    QString m_portName;
    SerialSettings m_settings;
    std::unique_ptr<QSerialPort> m_port;
    QString m_lostMessage;
    bool m_realBreaks = false;
};

// "8N1" and friends; empty when a value is out of range.
QString serialFrameText(const SerialSettings& settings);
// Why `settings` cannot be used, or empty when they can.
QString validateSerialSettings(const SerialSettings& settings);

}  // namespace cambench::comm
