#include "compax3_drive.h"

#include "compax3_syntax.h"

#include "model/compax3/compax3_value.h"

#include <QCoreApplication>

namespace cambench::comm {

namespace {

// The info string's fixed length plus some room; the longest value answer.
constexpr int kLongestInfo = 48;

}  // namespace

Compax3Drive::Compax3Drive(Transport& transport, QString protocolId, int address, int timeoutMs,
                           const LineTiming& line)
    : m_protocolId(std::move(protocolId)),
      m_backend(address),
      m_engine(transport, m_backend, EngineSettings{line, 2, timeoutMs}) {}

void Compax3Drive::setDevice(int device) {
    if (m_backend.address() >= 0) m_backend.setAddress(qBound(0, device, kCompax3LastAddress));
}

Result<Compax3Reply> Compax3Drive::exchange(const QByteArray& command, RetryPolicy retry,
                                            int longestReply, int maxAttempts) {
    Request request;
    request.label = QString::fromLatin1(command);
    request.message = command;
    request.longestReplyBytes = longestReply;
    request.retry = retry;
    request.maxAttempts = maxAttempts;
    // Every write can move the axis or change its power (a set's objects,
    // select and start, a jog, enable, disable, a restore's objects): none
    // of a job a STOP overtook leaves. The stop's own writes are no motion.
    request.motion = command.contains('=') && !m_stopping;
    // An answer with bytes no Compax3 sends was damaged on the line: this
    // attempt failed (a request that may be repeated is sent again).
    request.judge = [](const QByteArray& reply, QString& problem) {
        const Result<Compax3Reply> parsed = parseCompax3Reply(reply);
        if (parsed) return Verdict::Accept;
        problem = parsed.error().message;
        return Verdict::Retry;
    };
    const Result<QByteArray> answer = m_engine.send(request);
    if (!answer) return answer.error();
    const Result<Compax3Reply> reply = parseCompax3Reply(*answer);
    if (!reply)
        return Error::communication(
            QCoreApplication::translate("cambench::comm", "%1 answered %2: %3")
                .arg(m_backend.describe(), QString::fromLatin1(command), reply.error().message));
    if (reply->kind == Compax3Reply::Error)
        return compax3RefusalError(command, reply->code, dictionary().refusals());
    return reply;
}

Result<Compax3Identity> Compax3Drive::identity() {
    Result<Compax3Reply> info =
        exchange(compax3InfoCommand(), RetryPolicy::Idempotent, kLongestInfo);
    if (!info && info.error().kind == ErrorKind::DeviceError)
        // A syntax error: the line may have held bytes of something else
        // before (Detect tries other protocols first), and the drive read
        // them as part of this request. A read may be asked again.
        info = exchange(compax3InfoCommand(), RetryPolicy::Idempotent, kLongestInfo);
    if (!info) return info.error();
    if (info->kind != Compax3Reply::Value || !info->text.startsWith(QLatin1String("Compax3")))
        return Error::communication(
            QCoreApplication::translate("cambench::comm",
                                        "what answers is no Compax3: its info string is \"%1\"")
                .arg(info->text));
    Compax3Identity identity;
    identity.info = info->text;
    const Result<QString> serial = readObject(kCompax3Serial, false);
    if (!serial) return serial.error();
    identity.serial = *serial;
    return identity;
}

Result<QString> Compax3Drive::identify() {
    const Result<Compax3Identity> drive = identity();
    if (!drive) return drive.error();
    const QString where = m_backend.address() < 0
                              ? QString()
                              : QCoreApplication::translate("cambench::comm", ", address %1")
                                    .arg(m_backend.address());
    return QCoreApplication::translate("cambench::comm", "%1, serial number %2%3")
        .arg(drive->info, drive->serial, where);
}

Result<QString> Compax3Drive::probe() {
    if (m_backend.address() < 0) return DeviceConnection::probe();
    EngineSettings quick = m_engine.settings();
    quick.retries = 0;
    m_engine.setSettings(quick);
    const Result<QList<int>> found = scanBus(0, kCompax3LastAddress, {});
    if (!found) return found.error();
    if (found->isEmpty())
        return Error::communication(QCoreApplication::translate(
            "cambench::comm", "no Compax3 answered at any RS485 address 0..99"));
    m_backend.setAddress(found->first());
    return identify();
}

Result<QList<int>> Compax3Drive::scanBus(int first, int last, const ProgressFn& progress) {
    const int keep = m_backend.address();
    QList<int> found;
    for (int address = first; address <= last; ++address) {
        m_backend.setAddress(address);
        Request request;
        request.label = QStringLiteral("_? (address %1)").arg(address);
        request.message = compax3InfoCommand();
        request.longestReplyBytes = kLongestInfo;
        request.maxAttempts = 1;
        request.turnaroundMs = 30;  // a short look at each address
        request.silenceExpected = true;
        const Result<QByteArray> answer = m_engine.send(request);
        if (answer) {
            const Result<Compax3Reply> reply = parseCompax3Reply(*answer);
            if (reply && reply->text.startsWith(QLatin1String("Compax3"))) found << address;
        } else if (answer.error().kind == ErrorKind::Cancelled) {
            m_backend.setAddress(keep);
            return answer.error();
        }
        if (progress) progress(address - first + 1, last - first + 1);
    }
    m_backend.setAddress(keep);
    return found;
}

Result<QString> Compax3Drive::readObject(const Compax3ObjectId& id, bool hex) {
    return readValue(id, hex, 0);
}

Result<QString> Compax3Drive::readValue(const Compax3ObjectId& id, bool hex, int maxAttempts) {
    const QByteArray command = compax3ReadCommand(id, hex);
    const Result<Compax3Reply> reply =
        exchange(command, RetryPolicy::Idempotent, kLongestInfo, maxAttempts);
    if (!reply) return reply.error();
    if (reply->kind != Compax3Reply::Value)
        return Error::communication(
            QCoreApplication::translate("cambench::comm", "%1 answered %2 with \">\", not a value")
                .arg(m_backend.describe(), QString::fromLatin1(command)));
    return reply->text;
}

Status Compax3Drive::writeObject(const Compax3ObjectId& id, const QString& wireValue) {
    const QByteArray command = compax3WriteCommand(id, wireValue);
    // A value written twice is the same value; the control word is not a
    // value (its edges start and acknowledge): written once.
    const RetryPolicy retry =
        id == kCompax3ControlWord ? RetryPolicy::Never : RetryPolicy::Idempotent;
    return writeCommand(command, retry);
}

Status Compax3Drive::writeCommand(const QByteArray& command, RetryPolicy retry) {
    const Result<Compax3Reply> reply = exchange(command, retry);
    if (!reply) return reply.error();
    if (reply->kind != Compax3Reply::Ok)
        return Error::communication(
            QCoreApplication::translate("cambench::comm", "%1 answered %2 with \"%3\", not \">\"")
                .arg(m_backend.describe(), QString::fromLatin1(command), reply->text));
    return success();
}

Result<double> Compax3Drive::readNumber(const Compax3ObjectId& id, int maxAttempts) {
    const Result<QString> text = readValue(id, false, maxAttempts);
    if (!text) return text.error();
    const std::optional<double> number = compax3Number(*text);
    if (!number)
        return Error::communication(
            QCoreApplication::translate("cambench::comm",
                                        "%1 answered O%2 with \"%3\", not a number")
                .arg(m_backend.describe(), id.text(), *text));
    return *number;
}

Result<Compax3DriveStatus> Compax3Drive::status() {
    Compax3DriveStatus status;
    const Compax3ObjectId ids[] = {kCompax3StatusWord, kCompax3LastError, kCompax3Position,
                                   kCompax3LastSet, kCompax3ControlWord};
    double values[5] = {};
    for (int i = 0; i < 5; ++i) {
        const Result<double> value = readNumber(ids[i]);
        if (!value) return value.error();
        values[i] = *value;
    }
    status.status.word = quint16(values[0]);
    status.lastError = int(values[1]);
    status.position = values[2];
    status.lastSet = int(values[3]);
    status.controlWord = quint16(values[4]);
    return status;
}

}  // namespace cambench::comm
