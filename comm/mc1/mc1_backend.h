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
// Not built yet: the MC100MA's send window (a telegram must start within
// 2–4 ms after the card's 0xFF); lines to such cards need it.
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
    QByteArray resetInput() override;
    qint64 requestWireBytes(const Request& request) const override;
    qint64 replyWireBytes(const Request& request) const override;

    // What answers `telegram` on `variant`, from its request bytes.
    static Mc1Expectation expectationFor(Mc1Variant variant, const QByteArray& telegram);

private:
    Mc1Variant m_variant;
    bool m_probing = false;
    Mc1Expectation m_expected;
    QByteArray m_buffer;
};

}  // namespace cambench::comm
