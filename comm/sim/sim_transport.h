#pragma once

#include "sim_endpoint.h"
#include "sim_pacer.h"
#include "simulator_registry.h"

#include "comm/transport/transport_registry.h"

#include <QElapsedTimer>

#include <memory>

namespace cambench::comm {

// The in-process simulator behind the Transport interface ("--port sim"):
// write() hands the request to a SimEndpoint, and the replies become
// readable as the pacer lets their bytes arrive at the configured baud
// rate; read() also runs the endpoint's timers.
class SimTransport : public Transport {
public:
    // Any simulated line, of any device family: `line` behind the
    // transport, its replies paced by `pacer`; `description` for messages.
    SimTransport(std::unique_ptr<SimEndpoint> line, const SimPacer& pacer, QString description);
    explicit SimTransport(SimulatedLine line);

    Status open() override;
    void close() override;
    bool isOpen() const override { return m_open; }
    Status write(const QByteArray& bytes) override;
    Result<QByteArray> read(int timeoutMs) override;
    void discardInput() override;
    QString description() const override;

    SimEndpoint& line() { return *m_line; }
    const SimPacer& pacer() const { return m_pacer; }

private:
    qint64 nowUs() const { return m_clock.nsecsElapsed() / 1000; }
    // Runs the endpoint's timer when it is due.
    void pollLine();

    QString m_description;
    std::unique_ptr<SimEndpoint> m_line;
    SimPacer m_pacer;
    QElapsedTimer m_clock;
    PacedQueue m_pending;
    bool m_open = false;
};

// "sim" or "sim:key=value;..." as a Transport: the simulator of the family
// `protocol` (a registry id) belongs to builds the line; the keys are its own.
// Without a protocol, the device the port names (ConnectionSettings::protocol).
Result<std::unique_ptr<Transport>> makeSimTransport(const QString& port,
                                                    const SerialSettings& serial,
                                                    const QString& protocol = {});

// The protocol the keys of a simulator port name (SimulatorInfo::namedProtocol).
QString simPortProtocol(const QString& port);

// Adds "sim" and "sim:..." to `registry`.
void registerSimTransport(TransportRegistry& registry);

}  // namespace cambench::comm
