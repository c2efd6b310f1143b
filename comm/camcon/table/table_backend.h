#pragma once

#include "link_3964r.h"
#include "rk512.h"

#include "comm/engine/framing_backend.h"

namespace cambench::comm::table {

// The table interface's framing as a FramingBackend. A request message is
// one telegram (RK512 or a short command); Link3964R carries it with the
// PC's high priority, and the device's reply arrives as a 3964R transfer of
// its own, which the link acknowledges with DLE and hands up as a message.
//
// - The request counts as sent (`sent`) once the device has acknowledged
//   its block. A telegram received before that is no answer to it: the
//   device acts on a telegram only after taking it, so an earlier one is
//   left over from before and reported as Foreign.
// - A link failure (no DLE after every attempt, NAKs) ends the attempt.
//   For an idempotent request the link has then tried Timing3964R::attempts
//   times already; the engine's further attempts of the same request fail
//   at once with the same reason instead of trying six times more each.
// - RetryPolicy::Never and CheckAfter telegrams are not repeated by the link
//   once their block may have reached the device (Link3964R::Repeat): 3964R
//   has no sequence numbers, so a lost DLE would make the device execute
//   them twice.
// - resetInput() leaves the link as it is: the 3964R procedure answers the
//   partner and ends every transfer by itself (NAK after the character
//   delay), which dropping a half-received block would break.
class TableBackend : public FramingBackend {
public:
    explicit TableBackend(Rk512Variant variant, Timing3964R timing = {});

    Rk512Variant variant() const { return m_variant; }
    const Link3964R& link() const { return m_link; }
    const Timing3964R& timing() const { return m_timing; }
    // Attempts per telegram from now on (Detect's probe: one).
    void setAttempts(int attempts);

    QString describe() const override;
    QString checkHint() const override;
    void beginRequest(const Request& request) override;
    BackendStep startAttempt(const Request& request, int attempt, qint64 nowMs) override;
    BackendStep feed(QByteArrayView bytes, qint64 nowMs) override;
    BackendStep poll(qint64 nowMs) override;
    qint64 nextTimerMs() const override { return m_link.nextDeadlineMs(); }
    QByteArray resetInput() override;
    qint64 requestWireBytes(const Request& request) const override;
    qint64 replyWireBytes(const Request& request) const override;

private:
    BackendStep translate(Actions&& actions);

    Rk512Variant m_variant;
    Timing3964R m_timing;
    Link3964R m_link;
    RetryPolicy m_retry = RetryPolicy::Idempotent;  // of the request begun last
    bool m_awaitingReply = false;  // the device took our telegram: what comes now answers it
    QString m_finalFailure;        // the link gave up on the request begun last
    QByteArray m_unlogged;         // bytes fed but not yet handed up for the traffic log
};

}  // namespace cambench::comm::table
