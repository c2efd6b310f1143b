#include "transport_factory.h"

#include "serial_transport.h"
#include "tcp_transport.h"

#include "comm/sim/sim_port_config.h"
#include "comm/sim/sim_transport.h"

#include <QUrl>

namespace cambench::comm {

namespace {

const QLatin1String kTcpScheme("tcp://");

Result<std::unique_ptr<Transport>> makeTcpTransport(const QString& port) {
    const QUrl url(port, QUrl::StrictMode);
    const QString usage = QStringLiteral("write it as tcp://host:port, e.g. tcp://10.0.0.5:4001");
    if (!url.isValid() || url.host().isEmpty())
        return Error::usage(QStringLiteral("'%1' names no host; %2").arg(port, usage));
    if (url.port() < 1)
        return Error::usage(QStringLiteral("'%1' names no TCP port (1..65535); %2").arg(port, usage));
    if (!url.path().isEmpty() || url.hasQuery() || url.hasFragment() || !url.userInfo().isEmpty())
        return Error::usage(
            QStringLiteral("'%1' has more than a host and a port; %2").arg(port, usage));
    return std::unique_ptr<Transport>(
        std::make_unique<TcpTransport>(url.host(), quint16(url.port())));
}

}  // namespace

Result<std::unique_ptr<Transport>> makeTransport(const ConnectionSettings& connection) {
    const QString port = connection.port.trimmed();
    if (port.isEmpty())
        return Error::usage(QStringLiteral("no port given; name a serial port (/dev/ttyUSB0, "
                                           "COM3), tcp://host:port or sim"));
    if (isSimPort(port)) return makeSimTransport(port, connection.serial);
    if (port.startsWith(kTcpScheme, Qt::CaseInsensitive)) return makeTcpTransport(port);
    if (port.contains(QLatin1String("://")))
        return Error::usage(QStringLiteral("'%1': unknown scheme; use tcp://host:port, a serial "
                                           "port name or sim")
                                .arg(port));
    const QString invalid = validateSerialSettings(connection.serial);
    if (!invalid.isEmpty())
        return Error::usage(QStringLiteral("cannot use %1: %2").arg(port, invalid));
    return std::unique_ptr<Transport>(std::make_unique<SerialTransport>(port, connection.serial));
}

}  // namespace cambench::comm
