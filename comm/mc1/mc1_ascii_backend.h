#pragma once

#include "comm/engine/framing_backend.h"

namespace cambench::comm {

// The MC100's ASCII protocol as the request engine's framing backend: a
// request is one line with its CR; the answer is the next line (LF
// dropped), handed up without its CR.
class Mc1AsciiBackend : public FramingBackend {
public:
    QString describe() const override;
    QString checkHint() const override;
    void beginRequest(const Request&) override {}
    BackendStep startAttempt(const Request& request, int attempt, qint64 nowMs) override;
    BackendStep feed(QByteArrayView bytes, qint64 nowMs) override;
    QByteArray resetInput() override;
    qint64 requestWireBytes(const Request& request) const override;
    qint64 replyWireBytes(const Request& request) const override;

private:
    QByteArray m_buffer;
};

}  // namespace cambench::comm
