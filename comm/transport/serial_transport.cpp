#include "serial_transport.h"

#include "transport_logging.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QSerialPort>

#include <algorithm>

namespace cambench::comm {

namespace {

QSerialPort::Parity toParity(char parity) {
    switch (parity) {
        case 'E':
            return QSerialPort::EvenParity;
        case 'O':
            return QSerialPort::OddParity;
        case 'S':
            return QSerialPort::SpaceParity;
        case 'M':
            return QSerialPort::MarkParity;
        default:
            return QSerialPort::NoParity;
    }
}

QSerialPort::StopBits toStopBits(int stopBits) {
    switch (stopBits) {
        case 2:
            return QSerialPort::TwoStop;
        case 3:
            return QSerialPort::OneAndHalfStop;
        default:
            return QSerialPort::OneStop;
    }
}

QSerialPort::FlowControl toFlowControl(char flow) {
    switch (flow) {
        case 'H':
            return QSerialPort::HardwareControl;
        case 'S':
            return QSerialPort::SoftwareControl;
        default:
            return QSerialPort::NoFlowControl;
    }
}

bool isLineGone(QSerialPort::SerialPortError error) {
    return error != QSerialPort::NoError && error != QSerialPort::TimeoutError;
}

}  // namespace

QString validateSerialSettings(const SerialSettings& s) {
    if (s.baud <= 0)
        return QCoreApplication::translate("cambench::comm",
                                           "baud rate %1 is not a positive number")
            .arg(s.baud);
    if (s.dataBits < 5 || s.dataBits > 8)
        return QCoreApplication::translate("cambench::comm", "%1 data bits: use 5, 6, 7 or 8")
            .arg(s.dataBits);
    if (!QByteArrayView("NEOSM").contains(s.parity))
        return QCoreApplication::translate("cambench::comm", "parity '%1': use N, E, O, S or M")
            .arg(QChar(s.parity));
    if (s.stopBits < 1 || s.stopBits > 3)
        return QCoreApplication::translate("cambench::comm",
                                           "%1 stop bits: use 1, 2 or 3 (one and a half)")
            .arg(s.stopBits);
    if (!QByteArrayView("NHS").contains(s.flowControl))
        return QCoreApplication::translate(
                   "cambench::comm", "flow control '%1': use N (none), H (RTS/CTS) or S (XON/XOFF)")
            .arg(QChar(s.flowControl));
    return {};
}

QString serialFrameText(const SerialSettings& s) {
    if (!validateSerialSettings(s).isEmpty()) return {};
    const QString stop = s.stopBits == 3 ? QStringLiteral("1.5") : QString::number(s.stopBits);
    return QString::number(s.dataBits) + QChar(s.parity) + stop;
}

SerialTransport::SerialTransport(QString portName, SerialSettings settings)
    : m_portName(std::move(portName)), m_settings(settings) {}

SerialTransport::~SerialTransport() = default;

Status SerialTransport::open() {
    close();
    m_lostMessage.clear();
    const QString invalid = validateSerialSettings(m_settings);
    if (!invalid.isEmpty())
        return Error::usage(QCoreApplication::translate("cambench::comm", "cannot use %1: %2")
                                .arg(m_portName, invalid));

    // Any path is opened as given: QSerialPortInfo does not list
    // pseudo-terminals, yet they are ports like any other here.
    m_port = std::make_unique<QSerialPort>();
    m_port->setPortName(m_portName);
    m_port->setBaudRate(m_settings.baud);
    m_port->setDataBits(QSerialPort::DataBits(m_settings.dataBits));
    m_port->setParity(toParity(m_settings.parity));
    m_port->setStopBits(toStopBits(m_settings.stopBits));
    m_port->setFlowControl(toFlowControl(m_settings.flowControl));
    if (!m_port->open(QIODevice::ReadWrite)) {
        const QString reason = m_port->errorString();
        const auto error = m_port->error();
        m_port.reset();
        if (error == QSerialPort::PermissionError) {
            // Linux says "Permission denied" both for a user outside the
            // group that owns the port and for a port another program holds.
            return Error::communication(
                QCoreApplication::translate(
                    "cambench::comm",
                    "permission denied on %1 (%2): this user may not open the serial port, or "
                    "another program holds it. On Linux, add the user to the group dialout "
                    "(sudo usermod -aG dialout $USER), then log out and in again; close any "
                    "other program that uses the port.")
                    .arg(m_portName, reason));
        }
        QString hint = QCoreApplication::translate(
            "cambench::comm", "check the port name and that no other program uses it");
        if (error == QSerialPort::DeviceNotFoundError)
            hint = QCoreApplication::translate(
                "cambench::comm", "check the port name and that the adapter is plugged in");
        return Error::communication(
            QCoreApplication::translate("cambench::comm", "cannot open %1: %2; %3")
                .arg(m_portName, reason, hint));
    }

    // Pseudo-terminals and some adapters have no modem lines: the line works
    // without them, so a refusal is only worth a log line.
    if (m_settings.flowControl != 'H' && !m_port->setRequestToSend(m_settings.rts)) {
        qCInfo(commSerialLog) << "cannot set RTS on" << m_portName << ":" << m_port->errorString();
        m_port->clearError();
    }
    if (!m_port->setDataTerminalReady(m_settings.dtr)) {
        qCInfo(commSerialLog) << "cannot set DTR on" << m_portName << ":" << m_port->errorString();
        m_port->clearError();
    }
    m_port->clear(QSerialPort::AllDirections);
    qCInfo(commSerialLog) << "opened" << description();
    return success();
}

void SerialTransport::close() {
    if (!m_port) return;
    if (m_port->isOpen()) {
        m_port->close();
        qCInfo(commSerialLog) << "closed" << m_portName;
    }
    m_port.reset();
}

bool SerialTransport::isOpen() const {
    return m_port && m_port->isOpen();
}

Error SerialTransport::lose(const QString& action) {
    // A pulled USB adapter fails with EIO or ENODEV; a tty whose other end
    // hung up (a pty's master closed) reads as end of file, which
    // QSerialPort reports as ReadError.
    const auto error = m_port->error();
    const bool vanished = error == QSerialPort::ResourceError ||
                          error == QSerialPort::DeviceNotFoundError ||
                          error == QSerialPort::ReadError || error == QSerialPort::WriteError;
    if (vanished)
        m_lostMessage =
            QCoreApplication::translate("cambench::comm",
                                        "the port %1 disappeared (cable pulled or adapter "
                                        "removed); reconnect and retry")
                .arg(m_portName);
    else
        m_lostMessage =
            QCoreApplication::translate("cambench::comm", "%1 %2 failed: %3; reconnect and retry")
                .arg(action, m_portName, m_port->errorString());
    // errorString() may be a stale errno after an end of file; the code is not.
    qCWarning(commSerialLog) << m_lostMessage << "- QSerialPort error" << int(error);
    close();
    return Error::communication(m_lostMessage);
}

Error SerialTransport::notOpenError() const {
    if (!m_lostMessage.isEmpty()) return Error::communication(m_lostMessage);
    return Error::communication(
        QCoreApplication::translate("cambench::comm", "the port %1 is not open; connect first")
            .arg(m_portName));
}

int SerialTransport::writeTimeoutMs(qint64 bytes) const {
    // Twice the time on the wire (start, data, parity and stop bits, at most
    // 12 per character) plus a second for the OS and the adapter.
    const qint64 wireMs = bytes * 12 * 1000 / std::max(1, m_settings.baud);
    return int(std::min<qint64>(2 * wireMs + 1000, 600000));
}

Status SerialTransport::write(const QByteArray& bytes) {
    if (!isOpen()) return notOpenError();
    if (m_port->write(bytes) != bytes.size())
        return lose(QCoreApplication::translate("cambench::comm", "writing to"));
    const int timeoutMs = writeTimeoutMs(bytes.size());
    QDeadlineTimer deadline(timeoutMs);
    while (m_port->bytesToWrite() > 0) {
        if (deadline.hasExpired()) {
            m_port->clear(QSerialPort::Output);
            return Error::communication(
                QCoreApplication::translate(
                    "cambench::comm",
                    "could not send %1 bytes to %2 within %3 ms; check the flow "
                    "control setting (RTS/CTS needs the CTS line)")
                    .arg(bytes.size())
                    .arg(description())
                    .arg(timeoutMs));
        }
        const int slice = int(std::min<qint64>(kSliceMs, deadline.remainingTime()));
        if (!m_port->waitForBytesWritten(slice)) {
            if (isLineGone(m_port->error()))
                return lose(QCoreApplication::translate("cambench::comm", "writing to"));
            m_port->clearError();
        }
    }
    return success();
}

Result<QByteArray> SerialTransport::read(int timeoutMs) {
    if (!isOpen()) return notOpenError();
    QDeadlineTimer deadline(std::max(0, timeoutMs));
    while (m_port->bytesAvailable() == 0) {
        const int slice = int(std::min<qint64>(kSliceMs, deadline.remainingTime()));
        if (!m_port->waitForReadyRead(slice)) {
            if (isLineGone(m_port->error()))
                return lose(QCoreApplication::translate("cambench::comm", "reading from"));
            m_port->clearError();
        }
        if (deadline.hasExpired()) break;
    }
    QByteArray bytes = m_port->readAll();
    if (isLineGone(m_port->error()))
        return lose(QCoreApplication::translate("cambench::comm", "reading from"));
    return bytes;
}

void SerialTransport::discardInput() {
    if (!isOpen()) return;
    m_port->readAll();
    m_port->clear(QSerialPort::Input);
}

QString SerialTransport::description() const {
    return QStringLiteral("%1 at %2 %3")
        .arg(m_portName)
        .arg(m_settings.baud)
        .arg(serialFrameText(m_settings));
}

}  // namespace cambench::comm
