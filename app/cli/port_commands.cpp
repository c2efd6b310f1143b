// `ports`: the serial ports this PC has, with what tells USB adapters apart.
// Needs no device: the session is never opened.
#include "cli_output.h"
#include "commands.h"
#include "exit_codes.h"

#include "comm/ports/serial_port_list.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace cambench::cli {

int runPorts(CliSession&, CommandArgs& args) {
    const bool json = args.takeFlag(QStringLiteral("--json"));
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const QList<comm::SerialPortEntry> ports = comm::availableSerialPorts();
    if (json) {
        QJsonArray list;
        for (const comm::SerialPortEntry& port : ports) {
            QJsonObject entry{{QStringLiteral("port"), port.location},
                              {QStringLiteral("description"), port.description},
                              {QStringLiteral("manufacturer"), port.manufacturer},
                              {QStringLiteral("serialNumber"), port.serialNumber}};
            if (port.vendorId >= 0) entry.insert(QStringLiteral("vendorId"), port.vendorId);
            if (port.productId >= 0) entry.insert(QStringLiteral("productId"), port.productId);
            list << entry;
        }
        printOut(QString::fromUtf8(QJsonDocument(list).toJson(QJsonDocument::Indented)));
        return ExitOk;
    }
    if (ports.isEmpty()) {
        printOut(QStringLiteral(
            "No serial port found. Plug in the USB adapter and run `cambench-cli ports` again; "
            "a device server is reached as tcp://HOST:PORT.\n"));
        return ExitOk;
    }
    for (const comm::SerialPortEntry& port : ports) printOut(port.label() + QLatin1Char('\n'));
    return ExitOk;
}

}  // namespace cambench::cli
