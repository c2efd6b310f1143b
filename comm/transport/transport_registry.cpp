#include "transport_registry.h"

#include "serial_transport.h"
#include "tcp_transport.h"

#include <QCoreApplication>
#include <QUrl>

namespace cambench::comm {

namespace {

const QLatin1String kTcpScheme("tcp://");

Result<std::unique_ptr<Transport>> makeTcpTransport(const QString& port) {
    const QUrl url(port, QUrl::StrictMode);
    const QString usage = QCoreApplication::translate(
        "cambench::comm", "write it as tcp://host:port, e.g. tcp://10.0.0.5:4001");
    if (!url.isValid() || url.host().isEmpty())
        return Error::usage(QCoreApplication::translate("cambench::comm", "'%1' names no host; %2")
                                .arg(port, usage));
    if (url.port() < 1)
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "'%1' names no TCP port (1..65535); %2")
                .arg(port, usage));
    if (!url.path().isEmpty() || url.hasQuery() || url.hasFragment() || !url.userInfo().isEmpty())
        return Error::usage(QCoreApplication::translate("cambench::comm",
                                                        "'%1' has more than a host and a port; %2")
                                .arg(port, usage));
    return std::unique_ptr<Transport>(
        std::make_unique<TcpTransport>(url.host(), quint16(url.port())));
}

Result<std::unique_ptr<Transport>> makeSerialTransport(const ConnectionSettings& connection) {
    const QString port = connection.port.trimmed();
    if (port.contains(QLatin1String("://")))
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "'%1': unknown scheme; use tcp://host:port, a serial "
                                        "port name or sim")
                .arg(port));
    const QString invalid = validateSerialSettings(connection.serial);
    if (!invalid.isEmpty())
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "cannot use %1: %2").arg(port, invalid));
    return std::unique_ptr<Transport>(std::make_unique<SerialTransport>(port, connection.serial));
}

}  // namespace

TransportRegistry& TransportRegistry::instance() {
    static TransportRegistry registry;
    return registry;
}

void TransportRegistry::add(TransportScheme scheme) {
    for (TransportScheme& existing : m_schemes) {
        if (existing.name == scheme.name) {
            existing = std::move(scheme);  // registering again replaces
            return;
        }
    }
    m_schemes.append(std::move(scheme));
}

Result<std::unique_ptr<Transport>> TransportRegistry::make(
    const ConnectionSettings& connection) const {
    const QString port = connection.port.trimmed();
    if (port.isEmpty())
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "no port given; name a serial port (/dev/ttyUSB0, "
                                        "COM3), tcp://host:port or sim"));
    for (const TransportScheme& scheme : m_schemes) {
        if (!scheme.matches(port)) continue;
        ConnectionSettings trimmed = connection;
        trimmed.port = port;
        return scheme.make(trimmed);
    }
    return Error::usage(
        QCoreApplication::translate("cambench::comm", "'%1' names no port this program can open")
            .arg(port));
}

QString TransportRegistry::namedProtocol(const QString& port) const {
    const QString trimmed = port.trimmed();
    for (const TransportScheme& scheme : m_schemes) {
        if (!scheme.matches(trimmed)) continue;
        return scheme.namedProtocol ? scheme.namedProtocol(trimmed) : QString();
    }
    return {};
}

void registerLineTransports(TransportRegistry& registry) {
    registry.add(
        {QStringLiteral("tcp"),
         [](const QString& port) { return port.startsWith(kTcpScheme, Qt::CaseInsensitive); },
         [](const ConnectionSettings& connection) { return makeTcpTransport(connection.port); }});
    registry.add(
        {QStringLiteral("serial"), [](const QString&) { return true; }, makeSerialTransport});
}

Result<std::unique_ptr<Transport>> makeTransport(const ConnectionSettings& connection) {
    return TransportRegistry::instance().make(connection);
}

}  // namespace cambench::comm
