#pragma once

#include "comm/transport/transport.h"

#include <memory>

namespace cambench::comm {

// The transport the worker's link always talks to. Forwards to the
// connected transport; without one (never connected, disconnected, line
// lost) every call fails at once with a Communication error that says so.
// Remembers why the connected transport closed, for the Lost state.
class GuardedTransport : public Transport {
public:
    GuardedTransport();
    ~GuardedTransport() override;

    void attach(std::unique_ptr<Transport> transport);
    // Closes and drops the connected transport; later calls fail with
    // `reason`.
    void detach(const QString& reason);
    // A transport is attached but has closed itself (port gone, peer closed).
    bool lineLost() const { return m_inner && !m_inner->isOpen(); }
    QString lossMessage() const;
    // Why calls fail while no transport is attached.
    QString reason() const { return m_reason; }
    // The connected transport, or nullptr (tests reach a simulated line).
    Transport* connected() const { return m_inner.get(); }

    Status open() override;
    void close() override;
    bool isOpen() const override;
    Status write(const QByteArray& bytes) override;
    Result<QByteArray> read(int timeoutMs) override;
    void discardInput() override;
    QString description() const override;

private:
    Error notConnected() const { return Error::communication(m_reason); }
    void noteFailure(const Error& error);

    std::unique_ptr<Transport> m_inner;
    QString m_reason;
    QString m_lossMessage;
};

}  // namespace cambench::comm
