#pragma once

#include "mc1_catalogue.h"

#include "comm/engine/framing_backend.h"

namespace cambench::comm {

// MC-1 as the request engine's FramingBackend. A request message is a whole
// telegram (mc1Request: opcode, checksum, data); the answer it waits for
// follows from the variant's catalogue (opcode, length), so that the
// backend knows when an answer is complete. 0xFF synchronisation bytes are
// skipped. The message handed up is the single ACK or NAK byte, or the
// whole answer telegram.
//
// The MC100MA's single-FIFO cards send 0xFF every 5 or 10 ms and take a
// telegram only when it starts within 2 or 4 ms after one. Once the backend
// has seen a 0xFF on the line, each attempt waits for the next one and
// sends at once (a telegram sent before that, blind, is lost silently and
// its attempt times out; reads are then sent again in step).
class Mc1Backend : public FramingBackend {
public:
    explicit Mc1Backend(Mc1Variant variant);

    Mc1Variant variant() const { return m_variant; }
    void setVariant(Mc1Variant variant) { m_variant = variant; }
    // While probing, an RDVAR answer of either width is taken (its width
    // tells an MC100 from an MC200).
    void setProbing(bool probing) { m_probing = probing; }

    QString describe() const override;
    QString checkHint() const override;
    void beginRequest(const Request& request) override;
    BackendStep startAttempt(const Request& request, int attempt, qint64 nowMs) override;
    BackendStep feed(QByteArrayView bytes, qint64 nowMs) override;
    BackendStep poll(qint64 nowMs) override;
    qint64 nextTimerMs() const override { return m_waitingForSync ? m_syncDeadline : -1; }
    QByteArray resetInput() override;
    // The line carries the MC100MA's 0xFF synchronisation.
    bool synchronised() const { return m_syncSeen; }
    qint64 requestWireBytes(const Request& request) const override;
    qint64 replyWireBytes(const Request& request) const override;

    // What answers `telegram` on `variant`, from its request bytes; while
    // `probing`, an RDVAR answer of the other width too.
    static Mc1Expectation expectationFor(Mc1Variant variant, const QByteArray& telegram,
                                         bool probing = false);

private:
    // Hands up every answer complete in the buffer.
    void takeAnswers(BackendStep& step);

    Mc1Variant m_variant;
    bool m_probing = false;
    Mc1Expectation m_expected;
    QByteArray m_buffer;
    bool m_syncSeen = false;
    bool m_waitingForSync = false;
    QByteArray m_held;  // the telegram waiting for its 0xFF
    qint64 m_syncDeadline = -1;
};

}  // namespace cambench::comm
