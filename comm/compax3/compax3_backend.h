#pragma once

#include "comm/engine/cr_line_backend.h"

namespace cambench::comm {

// The Compax3 ASCII protocol as the request engine's framing backend: a
// request's message is the command ("O680,5"); the backend puts the drive's
// address in front on RS485 and the CR behind. The answer is the next
// CR-ended line, handed up as it came (with an RS485 '*'; parseCompax3Reply
// reads both).
class Compax3Backend : public CrLineBackend {
public:
    // How late an answer may still come (FramingBackend::lateAnswerWindowMs):
    // a Compax3 answer carries nothing that ties it to its request. No
    // manual page gives the drive's answer time; the public client waits
    // 0.4 s for every answer (its serial timeout). We wait 1 s past the
    // first-byte time, 2.5 times that: provisional (README, reading C10).
    static constexpr int kLateAnswerWindowMs = 1000;

    // `address` 0..99 on RS485; -1 on RS232 (no address).
    explicit Compax3Backend(int address) : m_address(address) {}
    void setAddress(int address) { m_address = address; }
    int address() const { return m_address; }

    QString describe() const override;
    QString checkHint() const override;
    qint64 requestWireBytes(const Request& request) const override;
    qint64 replyWireBytes(const Request& request) const override;
    int lateAnswerWindowMs() const override { return kLateAnswerWindowMs; }

protected:
    QByteArray requestLine(const Request& request) const override;

private:
    int m_address;
};

}  // namespace cambench::comm
