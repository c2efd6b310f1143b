#pragma once

#include "device_connection.h"
#include "id_registry.h"
#include "protocol_option.h"
#include "protocol_settings.h"

#include "comm/engine/line_timing.h"
#include "comm/transport/transport.h"
#include "model/result.h"

#include <QList>
#include <QString>

#include <functional>
#include <memory>

namespace cambench::comm {

// What the rest of CamBench knows of one protocol: its name, the family of
// devices it reaches, its default line, the options it takes, and how to
// open a device connection over a transport. Protocols register themselves from app/
// (one line each); nothing else lists them.
struct ProtocolInfo {
    QString id;        // "standard": the CLI's --protocol value, the settings key
    QString familyId;  // "camcon"
    QString title;     // "CamCon ASCII, Multiuser (RS485)" (English; ui/ translates)
    // How the connection page lists it among its family's protocols,
    // "Multiuser (RS485 bus)"; empty: the title. And a line it shows below
    // its fields ("RS485, 115200 8N1 unless set otherwise in the drive").
    // Both English, written with QT_TRANSLATE_NOOP("cambench::comm", ...).
    QString choiceTitle;
    QString note;
    // Its settings beside the line's, each declared once: the command
    // line, a machine file and the connection page read them from here
    // (protocol_options.h).
    QList<ProtocolOption> options;
    SerialSettings defaultSerial;
    bool isBus = false;  // devices are addressed by number (and may be scanned)
    int lastDevice = 0;  // a bus: the highest device number (CamCon Multiuser: 63)
    // A bus whose devices a person knows by their address (a Compax3 on
    // RS485), not by a device number: lists and messages say "address".
    bool numbersAreAddresses = false;
    // Its probe only listens (a token bus, whose users other protocols'
    // bytes would disturb): Detect tries it before the others.
    bool listeningProbe = false;
    std::function<std::unique_ptr<ProtocolSettings>()> makeSettings;
    // Opens the device connection over an open transport. `line` carries
    // the baud rate and character size the timeouts derive from.
    std::function<Result<std::unique_ptr<DeviceConnection>>(
        Transport& transport, const ProtocolSettings& settings, const LineTiming& line)>
        connect;
};

class ProtocolRegistry : public IdRegistry<ProtocolInfo, &ProtocolInfo::id> {
public:
    static ProtocolRegistry& instance();
};

// The line timing a serial setting gives: bits per byte from data bits,
// parity and stop bits.
LineTiming lineTimingFor(const SerialSettings& serial);

}  // namespace cambench::comm
