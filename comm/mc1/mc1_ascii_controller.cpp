#include "mc1_ascii_controller.h"

#include "mc1_ascii.h"
#include "mc1_link.h"

#include <QCoreApplication>

namespace cambench::comm {

namespace {

// The longest answer line: a 24-bit value with its sign and CR LF.
constexpr int kLongestAnswer = 10;

}  // namespace

Mc1AsciiController::Mc1AsciiController(Transport& transport, int timeoutMs, const LineTiming& line)
    : m_engine(transport, m_backend, mc1EngineSettings(line, 2, timeoutMs)) {}

QString Mc1AsciiController::variantSource() const {
    return QCoreApplication::translate("cambench::comm",
                                       "ASCII protocol, which looks alike on V1 and V2");
}

Result<QByteArray> Mc1AsciiController::exchange(const QByteArray& line, RetryPolicy retry,
                                                bool writes) {
    Request request;
    request.label = QString::fromLatin1(line.trimmed());
    request.message = line;
    request.longestReplyBytes = kLongestAnswer;
    request.retry = retry;
    // A write changes what the PLC program works with: none of a job a
    // STOP overtook leaves (mc1MayMove).
    request.motion = writes;
    return m_engine.send(request);
}

Result<Mc1Variant> Mc1AsciiController::ensureIdentified() {
    if (m_identified) return variant();
    Result<QByteArray> answer = exchange(mc1AsciiReadVariable(1));
    if (!answer) return answer.error();
    Result<qint32> value = mc1AsciiValue(*answer);
    if (!value && value.error().kind == ErrorKind::DeviceError) {
        // ERR: the line may have held bytes of something else before (Detect
        // tries other protocols first), and they became part of this one.
        // A read may be asked again.
        answer = exchange(mc1AsciiReadVariable(1));
        if (!answer) return answer.error();
        value = mc1AsciiValue(*answer);
    }
    if (!value)
        return Error::communication(
            QCoreApplication::translate("cambench::comm",
                                        "no MC100 answers in ASCII reading V1: %1")
                .arg(value.error().message));
    m_identified = true;
    return variant();
}

Result<QString> Mc1AsciiController::identify() {
    const Result<Mc1Variant> identified = ensureIdentified();
    if (!identified) return identified.error();
    return QCoreApplication::translate("cambench::comm", "MC100 (ASCII protocol)");
}

Result<DeviceIdentity> Mc1AsciiController::readIdentity() {
    const Result<Mc1Variant> identified = ensureIdentified();
    if (!identified) return identified.error();
    DeviceIdentity identity;
    identity.set(QStringLiteral("variant"), QStringLiteral("mc100"));
    return identity;
}

Result<qint64> Mc1AsciiController::readVariable(int number) {
    if (const Result<Mc1Variant> identified = ensureIdentified(); !identified)
        return identified.error();
    const Result<QByteArray> answer = exchange(mc1AsciiReadVariable(number));
    if (!answer) return answer.error();
    const Result<qint32> value = mc1AsciiValue(*answer);
    if (!value) return value.error();
    return qint64(*value);
}

Status Mc1AsciiController::writeVariable(int number, qint64 value) {
    if (value < kMc1Ascii24Min || value > kMc1Ascii24Max)
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "V%1 of the MC100 holds %2 to %3 (24 bits), not %4")
                .arg(number)
                .arg(kMc1Ascii24Min)
                .arg(kMc1Ascii24Max)
                .arg(value));
    if (const Result<Mc1Variant> identified = ensureIdentified(); !identified)
        return identified.error();
    const Result<QByteArray> line = mc1AsciiWriteVariable(number, qint32(value));
    if (!line) return line.error();
    const Result<QByteArray> answer = exchange(*line, RetryPolicy::Idempotent, true);
    if (!answer) return answer.error();
    return mc1AsciiOk(*answer);
}

Result<QList<bool>> Mc1AsciiController::readPoints(const QList<Mc1Point>& points,
                                                   const ProgressFn& progress) {
    if (const Result<Mc1Variant> identified = ensureIdentified(); !identified)
        return identified.error();
    QList<bool> values;
    for (const Mc1Point& point : points) {
        // Numbers the MC100 lacks are refused here, not sent.
        if (const Result<Mc1BitAddress> address = mc1BitAddress(point, false); !address)
            return address.error();
        const Result<QByteArray> answer = exchange(mc1AsciiReadPoint(point));
        if (!answer) return answer.error();
        const Result<bool> bit = mc1AsciiBit(*answer);
        if (!bit) return bit.error();
        values << *bit;
        if (progress) progress(values.size(), points.size());
    }
    return values;
}

Result<bool> Mc1AsciiController::writePoint(const Mc1Point& point, bool on) {
    if (const Result<Mc1BitAddress> address = mc1BitAddress(point, false); !address)
        return address.error();
    const Result<QByteArray> line = mc1AsciiWritePoint(point, on);
    if (!line) return line.error();
    if (const Result<Mc1Variant> identified = ensureIdentified(); !identified)
        return identified.error();
    // It acts (an output switches a machine part): sent once, as WRBIT is.
    const Result<QByteArray> answer = exchange(*line, RetryPolicy::Never, true);
    const Result<QList<bool>> back = readPoints({point}, {});
    if (!answer) {
        if (answer.error().kind != ErrorKind::Communication) return answer.error();
        // What the point holds now says whether the write took.
        if (back && back->first() == on) return on;
        return mc1LostAnswer(
            QString::fromLatin1(line->trimmed()), answer.error(),
            back ? QStringLiteral("%1 = %2").arg(mc1PointText(point)).arg(back->first() ? 1 : 0)
                 : QCoreApplication::translate("cambench::comm", "reading it failed too: %1")
                       .arg(back.error().message));
    }
    if (const Status ok = mc1AsciiOk(*answer); !ok) return ok.error();
    if (!back) return back.error();
    return back->first();
}

Result<QByteArray> Mc1AsciiController::readExternalPage(quint8 page, const ProgressFn& progress) {
    if (page != mc1ExternalFlagPage(false))
        return notInAscii(
            QCoreApplication::translate("cambench::comm", "external RAM page %1 (only the flags')")
                .arg(page));
    // The flags' page, flag by flag: every one of its 2048 bits is a flag.
    QList<Mc1Point> flags;
    for (int index = 0; index < 2048; ++index) flags << mc1ExternalFlagAt(index, false);
    const Result<QList<bool>> bits = readPoints(flags, progress);
    if (!bits) return bits.error();
    QByteArray bytes(256, '\0');
    for (int index = 0; index < bits->size(); ++index)
        if (bits->at(index))
            bytes[index >> 3] = char(quint8(bytes[index >> 3]) | (1u << (index & 7)));
    return bytes;
}

Error Mc1AsciiController::notInAscii(const QString& what) const {
    return Error::unsupported(QCoreApplication::translate(
                                  "cambench::comm",
                                  "the MC100's ASCII protocol has no requests for %1; an MC200 V2 "
                                  "over the binary protocol (mc1) has")
                                  .arg(what));
}

Result<Mc1ProgramStatus> Mc1AsciiController::programStatus() {
    return notInAscii(QCoreApplication::translate("cambench::comm", "the program status"));
}

Result<Mc1Done<Mc1ProgramStatus>> Mc1AsciiController::programCommand(Mc1ProgramCommand command) {
    return notInAscii(mc1ProgramCommandText(command));
}

Result<Mc1Axes> Mc1AsciiController::axes() {
    return Mc1Axes{{},
                   QCoreApplication::translate(
                       "cambench::comm", "none: the MC100's ASCII protocol has no axis requests")};
}

Result<Mc1AxisState> Mc1AsciiController::axisState(int) {
    return notInAscii(QCoreApplication::translate("cambench::comm", "axes"));
}

Result<qint32> Mc1AsciiController::axisValue(int, Mc1AxisValue) {
    return notInAscii(QCoreApplication::translate("cambench::comm", "axes"));
}

Result<Mc1AxisDone> Mc1AsciiController::axisCommand(int axis, Mc1AxisCommand command,
                                                    qint32 value) {
    return notInAscii(mc1AxisCommandText(axis, command, value));
}

Result<QByteArray> Mc1AsciiController::readMemory(int, int, const ProgressFn&) {
    return notInAscii(QCoreApplication::translate("cambench::comm", "memory"));
}

Status Mc1AsciiController::writeMemory(int, const QByteArray&, const ProgressFn&) {
    return notInAscii(QCoreApplication::translate("cambench::comm", "memory"));
}

}  // namespace cambench::comm
