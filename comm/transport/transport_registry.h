#pragma once

#include "transport.h"

#include <QList>

#include <functional>
#include <memory>

namespace cambench::comm {

// One kind of port name: "tcp://host:port", "sim:...", or a serial port.
struct TransportScheme {
    QString name;  // "tcp", "sim", "serial": for messages
    std::function<bool(const QString& port)> matches;
    // Makes the transport, not opened yet; a Usage error when the name or
    // the settings cannot be used.
    std::function<Result<std::unique_ptr<Transport>>(const ConnectionSettings& connection)> make;
    // The protocol a port's own name says its device speaks (a simulator
    // port "sim:protocol=3964r-n96"); empty when the name says none. Unset
    // for ports whose names never say.
    std::function<QString(const QString& port)> namedProtocol = nullptr;
};

// The transports CamBench can open, registered from app/ (one line each):
// nothing in comm/transport knows the simulator.
class TransportRegistry {
public:
    static TransportRegistry& instance();

    // Schemes are tried in the order added; add the catch-all serial last.
    void add(TransportScheme scheme);
    Result<std::unique_ptr<Transport>> make(const ConnectionSettings& connection) const;
    // TransportScheme::namedProtocol of the scheme `port` matches.
    QString namedProtocol(const QString& port) const;

private:
    QList<TransportScheme> m_schemes;
};

// Adds tcp:// and the serial ports (the catch-all) to `registry`.
void registerLineTransports(TransportRegistry& registry);

// The transport `connection.port` names (TransportRegistry::instance()).
Result<std::unique_ptr<Transport>> makeTransport(const ConnectionSettings& connection);

}  // namespace cambench::comm
