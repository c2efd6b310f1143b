#pragma once

#include "framing_backend.h"

#include <optional>

namespace cambench::comm {

// Splits the next CR-ended line off `buffer` without its CR (a LF some
// terminals add is dropped); nullopt while no line is complete.
std::optional<QByteArray> takeCrLine(QByteArray& buffer);

// A transparent line protocol as the request engine's framing backend (the
// MC100's ASCII protocol, the Compax3's): a request is sent as
// requestLine() makes it; every CR-ended line that comes back is one
// message, handed up without its CR.
class CrLineBackend : public FramingBackend {
public:
    void beginRequest(const Request&) override {}
    BackendStep startAttempt(const Request& request, int attempt, qint64 nowMs) override;
    BackendStep feed(QByteArrayView bytes, qint64 nowMs) override;
    QByteArray resetInput() override;

protected:
    // The wire bytes of `request`; by default its message as it is.
    virtual QByteArray requestLine(const Request& request) const { return request.message; }

private:
    QByteArray m_buffer;
};

}  // namespace cambench::comm
