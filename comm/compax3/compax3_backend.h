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
    // `address` 0..99 on RS485; -1 on RS232 (no address).
    explicit Compax3Backend(int address) : m_address(address) {}
    void setAddress(int address) { m_address = address; }
    int address() const { return m_address; }

    QString describe() const override;
    QString checkHint() const override;
    qint64 requestWireBytes(const Request& request) const override;
    qint64 replyWireBytes(const Request& request) const override;

protected:
    QByteArray requestLine(const Request& request) const override;

private:
    int m_address;
};

}  // namespace cambench::comm
