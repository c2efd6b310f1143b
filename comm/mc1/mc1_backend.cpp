#include "mc1_backend.h"

#include <QCoreApplication>

namespace cambench::comm {

Mc1Backend::Mc1Backend(Mc1Variant variant) : m_variant(variant) {}

QString Mc1Backend::describe() const {
    return QCoreApplication::translate("cambench::comm", "the %1").arg(mc1VariantName(m_variant));
}

QString Mc1Backend::checkHint() const {
    return QCoreApplication::translate(
        "cambench::comm",
        "check the cable (MC100: RxD/TxD crossed; MC200: 1:1, and DTR high, RTS low power its "
        "interface), the baud rate (MC100: 9600) and the controller's variant");
}

Mc1Expectation Mc1Backend::expectationFor(Mc1Variant variant, const QByteArray& telegram,
                                          bool probing) {
    const Mc1Telegram* row = mc1RequestRow(variant, telegram);
    if (!row) return {};
    Mc1Expectation expected = mc1ExpectedAnswer(*row, telegram.mid(row->command >= 0 ? 3 : 2));
    if (probing && row->op == Mc1Op::ReadVariable) {
        // The other width's row: an MC200's if `variant` is an MC100.
        const Mc1Variant other = isMc200(variant) ? Mc1Variant::Mc100V1 : Mc1Variant::Mc200V1;
        const Mc1Expectation theirs = expectationFor(other, telegram);
        expected.otherOpcode = theirs.opcode;
        expected.otherLength = theirs.length;
    }
    return expected;
}

void Mc1Backend::beginRequest(const Request& request) {
    m_expected = expectationFor(m_variant, request.message, m_probing);
}

namespace {
// Two periods of the slower card (10 ms) and more: a line whose 0xFF stop
// is no longer an MC100MA's (or no longer there).
constexpr qint64 kSyncWaitMs = 100;
}  // namespace

BackendStep Mc1Backend::startAttempt(const Request& request, int, qint64 nowMs) {
    BackendStep step;
    if (m_syncSeen) {
        m_waitingForSync = true;
        m_held = request.message;
        m_syncDeadline = nowMs + kSyncWaitMs;
        return step;
    }
    step.write = request.message;
    step.sent = true;
    return step;
}

BackendStep Mc1Backend::poll(qint64 nowMs) {
    BackendStep step;
    if (!m_waitingForSync || nowMs < m_syncDeadline) return step;
    m_waitingForSync = false;
    m_syncSeen = false;  // the next attempt goes out without waiting
    step.linkFailure =
        QCoreApplication::translate("cambench::comm",
                                    "no 0xFF synchronisation byte from the MC100MA for %1 ms")
            .arg(kSyncWaitMs);
    return step;
}

BackendStep Mc1Backend::feed(QByteArrayView input, qint64) {
    BackendStep step;
    for (const char byte : input) {
        // A 0xFF between telegrams is the MC100MA's synchronisation; inside
        // an answer it is a data byte.
        if (m_buffer.isEmpty() && quint8(byte) == kMc1Sync) {
            m_syncSeen = true;
            if (m_waitingForSync) {
                // The window is open now: the telegram goes out at once.
                m_waitingForSync = false;
                step.write = m_held;
                step.sent = true;
            }
            continue;
        }
        m_buffer.append(byte);
        takeAnswers(step);
    }
    return step;
}

void Mc1Backend::takeAnswers(BackendStep& step) {
    while (!m_buffer.isEmpty()) {
        const QByteArray before = m_buffer;
        const std::optional<Result<Mc1Answer>> answer = takeMc1Answer(m_buffer, m_expected);
        if (!answer) return;
        Incoming in;
        const qsizetype used = before.size() - m_buffer.size();
        in.wire = before.left(used > 0 ? used : before.size());
        if (!answer->ok()) {
            in.kind = Incoming::Damaged;
            in.detail = answer->error().message;
        } else if ((*answer)->kind == Mc1Answer::Kind::Data) {
            in.message = in.wire.mid(in.wire.size() - (*answer)->data.size() - 2);
        } else {
            in.message =
                QByteArray(1, char((*answer)->kind == Mc1Answer::Kind::Ack ? kMc1Ack : kMc1Nak));
        }
        step.incoming << in;
    }
}

QByteArray Mc1Backend::resetInput() {
    QByteArray dropped = m_buffer;
    m_buffer.clear();
    m_waitingForSync = false;
    return dropped;
}

qint64 Mc1Backend::requestWireBytes(const Request& request) const {
    return request.message.size();
}

qint64 Mc1Backend::replyWireBytes(const Request& request) const {
    return std::max<qint64>(expectationFor(m_variant, request.message).length,
                            request.longestReplyBytes);
}

}  // namespace cambench::comm
