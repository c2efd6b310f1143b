#include "table_backend.h"

#include "frame_3964r.h"
#include "table_logging.h"

#include <QCoreApplication>

#include <utility>

namespace cambench::comm::table {

namespace {

// STX and the partner's DLE before a block, its DLE after it.
constexpr int kHandshakeBytes = 3;
// DLE ETX BCC after the data.
constexpr int kBlockTrailerBytes = 3;

}  // namespace

TableBackend::TableBackend(Rk512Variant variant, Timing3964R timing)
    : m_variant(variant), m_timing(timing), m_link(Link3964R::Priority::High, timing) {}

void TableBackend::setAttempts(int attempts) {
    m_timing.attempts = attempts;
    m_link = Link3964R(Link3964R::Priority::High, m_timing);
}

QString TableBackend::describe() const {
    return QCoreApplication::translate("cambench::comm", "the device (%1)")
        .arg(QLatin1String(rk512VariantInfo(m_variant).name));
}

QString TableBackend::checkHint() const {
    const Rk512VariantInfo& info = rk512VariantInfo(m_variant);
    return QCoreApplication::translate(
               "cambench::comm",
               "check the cable, that the device's serial mode (menu \"Ser:\") is %1 "
               "and the line %2 8%3%4")
        .arg(QLatin1String(info.name))
        .arg(info.baudRate)
        .arg(QChar::fromLatin1(info.parity))
        .arg(1);
}

void TableBackend::beginRequest(const Request& request) {
    m_retry = request.retry;
    m_awaitingReply = false;
    m_finalFailure.clear();
}

BackendStep TableBackend::startAttempt(const Request& request, int attempt, qint64 nowMs) {
    BackendStep step;
    if (!m_finalFailure.isEmpty()) {
        step.linkFailure = m_finalFailure;
        return step;
    }
    if (m_link.sending()) {
        // Cannot happen while the engine waits for every transfer to end;
        // a stuck link must not block the line for good.
        qCWarning(commTableLog) << "a telegram was still being sent at attempt" << attempt << "of"
                                << request.label << "; link reset";
        m_link.reset();
    }
    m_awaitingReply = false;
    const Link3964R::Repeat repeat = m_retry == RetryPolicy::Idempotent
                                         ? Link3964R::Repeat::Always
                                         : Link3964R::Repeat::OnlyUnread;
    return translate(m_link.send(request.message, nowMs, repeat));
}

BackendStep TableBackend::feed(QByteArrayView bytes, qint64 nowMs) {
    m_unlogged += bytes;
    return translate(m_link.feed(bytes, nowMs));
}

BackendStep TableBackend::poll(qint64 nowMs) {
    return translate(m_link.poll(nowMs));
}

BackendStep TableBackend::translate(Actions&& actions) {
    for (const QString& line : std::as_const(actions.log)) qCDebug(commTableLog) << line;
    BackendStep step;
    step.write = std::move(actions.write);
    if (actions.sendDone) {
        step.sent = true;
        m_awaitingReply = true;
    }
    if (actions.sendFailed) {
        step.linkFailure = *actions.sendFailed;
        // Only an idempotent telegram has had all its link attempts here
        // (the others may stop after one, and the engine decides on them).
        if (m_retry == RetryPolicy::Idempotent) m_finalFailure = *actions.sendFailed;
    }
    for (QByteArray& telegram : actions.received) {
        Incoming in;
        in.wire = std::exchange(m_unlogged, {});
        if (m_awaitingReply) {
            in.kind = Incoming::Message;
            in.message = std::move(telegram);
        } else {
            in.kind = Incoming::Foreign;
            in.detail = QCoreApplication::translate(
                "cambench::comm", "a telegram before the device took the request");
            qCDebug(commTableLog) << "ignoring a telegram received before the request was "
                                     "acknowledged:"
                                  << telegram.toHex(' ');
        }
        step.incoming.append(std::move(in));
    }
    // Handshake bytes (DLE, NAK, the STX of a transfer) go to the log as
    // they come; a block being received waits until it is complete.
    if (!m_unlogged.isEmpty() && m_link.bufferedBytes() == 0) {
        Incoming control;
        control.kind = Incoming::Garbage;
        control.wire = std::exchange(m_unlogged, {});
        control.detail = QCoreApplication::translate(
            "cambench::comm", "3964R handshake, or a block answered with NAK");
        step.incoming.append(std::move(control));
    }
    return step;
}

QByteArray TableBackend::resetInput() {
    return std::exchange(m_unlogged, {});
}

qint64 TableBackend::requestWireBytes(const Request& request) const {
    return kHandshakeBytes + encodeBlock3964r(request.message).size();
}

qint64 TableBackend::replyWireBytes(const Request& request) const {
    // Every data byte may be a doubled DLE.
    return kHandshakeBytes + kBlockTrailerBytes + 2 * qint64(request.longestReplyBytes);
}

}  // namespace cambench::comm::table
