#include "serial_transport.h"

#include "transport_logging.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QSerialPort>

#include "break_marks.h"

#include <QFileInfo>
#include <QThread>

#include <algorithm>

#ifdef Q_OS_LINUX
#include <termios.h>
#endif
#ifdef Q_OS_UNIX
#include <poll.h>
#endif

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
    enableBreakMarks();
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

bool SerialTransport::isPseudoTerminal() const {
    // Unix98 pseudo-terminals (what socat and cambench-sim hand out).
    return QFileInfo(m_portName).canonicalFilePath().startsWith(QLatin1String("/dev/pts/"));
}

void SerialTransport::enableBreakMarks() {
    // A pseudo-terminal carries no breaks: the marks pass as bytes (P12).
    m_realBreaks = false;
    if (!m_settings.inBandBreaks || isPseudoTerminal()) return;
#ifdef Q_OS_LINUX
    termios tio{};
    const int fd = int(m_port->handle());
    if (fd >= 0 && tcgetattr(fd, &tio) == 0) {
        // Breaks and bytes with a framing error read as FF 00 00 / FF 00 x,
        // a data FF as FF FF; nothing is ignored or turned into a signal.
        tio.c_iflag |= PARMRK | INPCK;
        tio.c_iflag &= ~tcflag_t(IGNBRK | BRKINT | IGNPAR | ISTRIP);
        if (tcsetattr(fd, TCSANOW, &tio) == 0) {
            m_realBreaks = true;
            qCInfo(commSerialLog) << "breaks marked in the input of" << m_portName;
            return;
        }
    }
#endif
    qCWarning(commSerialLog) << "cannot mark breaks in the input of" << m_portName
                             << "- a bus that needs breaks will not work on it";
}

bool SerialTransport::lineGone() {
    const QSerialPort::SerialPortError error = m_port->error();
    if (!isLineGone(error)) return false;
    // QSerialPort also reports a read that found nothing (EAGAIN: its read
    // notifier fired after a blocking wait had taken the bytes) as
    // ResourceError or, with a stale errno, ReadError. Only a hang-up (a pty
    // whose other end closed, an adapter gone) means the line is gone.
    if (error != QSerialPort::ReadError && error != QSerialPort::ResourceError) return true;
#ifdef Q_OS_UNIX
    pollfd look{int(m_port->handle()), POLLIN, 0};
    if (::poll(&look, 1, 0) >= 0 && !(look.revents & (POLLHUP | POLLERR | POLLNVAL))) {
        qCDebug(commSerialLog) << "a read found nothing on" << m_portName << "- not a lost line";
        m_port->clearError();
        return false;
    }
#endif
    return true;
}

Status SerialTransport::writeWithBreaks(const QByteArray& bytes) {
    QByteArray pending = bytes;
    // A break: the line at 0 for 2 character times, then idle for 2 (docs/protocols/cambus.md).
    const int charUs = int(10 * 1000000LL / std::max(1, m_settings.baud));
    for (const MarkedRead& piece : takeBreakMarked(pending)) {
        if (piece.kind == MarkedRead::Data) {
            if (const Status written = writeRaw(piece.data); !written) return written;
            continue;
        }
        if (!m_port->setBreakEnabled(true))
            return lose(QCoreApplication::translate("cambench::comm", "sending a break on"));
        QThread::usleep(quint64(std::max(2 * charUs, 1000)));
        m_port->setBreakEnabled(false);
        QThread::usleep(quint64(2 * charUs));
    }
    return success();
}

Status SerialTransport::write(const QByteArray& bytes) {
    if (!isOpen()) return notOpenError();
    if (m_realBreaks) return writeWithBreaks(bytes);
    return writeRaw(bytes);
}

Status SerialTransport::writeRaw(const QByteArray& bytes) {
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
            if (lineGone())
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
            if (lineGone())
                return lose(QCoreApplication::translate("cambench::comm", "reading from"));
            m_port->clearError();
        }
        if (deadline.hasExpired()) break;
    }
    QByteArray bytes = m_port->readAll();
    if (lineGone()) return lose(QCoreApplication::translate("cambench::comm", "reading from"));
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
