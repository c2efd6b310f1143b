#pragma once

#include "comm/sim/sim_faults.h"
#include "comm/sim/simulator_registry.h"

#include "comm/camcon/ascii/frame.h"
#include "comm/camcon/table/rk512.h"
#include "comm/transport/transport.h"
#include "model/result.h"

#include <QList>
#include <QString>

#include <optional>

namespace cambench::comm {

// How to build a simulated line: from a port string ("sim",
// "sim:devices=0,5;baud=38400;corrupt=0.01") or from cambench-sim's options.
struct SimPortConfig {
    QList<int> devices{0};           // device numbers 0..63
    std::optional<Framing> framing;  // unset: Multiuser if more than one device
    // Set: the device speaks the table interface (3964R/RK512) instead of ASCII.
    std::optional<table::Rk512Variant> tableVariant;
    // The devices are users of a Cam-BUS (token bus) instead.
    bool camBus = false;
    QList<int> displays;     // Cam-BUS: display users; the i-th polls the i-th device
    int pcAnswerMs = 10;     // Cam-BUS: how long the simulated users wait for the PC (P11: 10)
    int silentAfterMs = 0;   // Cam-BUS: the dead devices fall silent then (0: from the start)
    int reinitAfterMs = -1;  // Cam-BUS: >= 0: a second initialisation phase then
    int baud = 9600;
    bool throttle = true;  // false: bytes arrive at once
    int fill = 0;          // > 0: benchmark cams per track instead of the demo cams
    int users = -1;        // >= 0: this many users instead of the demo's two
    // Analogue outputs 0..14 (area 203 word 38); 0: a CamCon without any,
    // whose areas 241..254 answer RK512 error 20.
    int analogueOutputs = 14;
    // Another identity than the demo device's, for the two different devices
    // a test or a walk needs: the firmware date (?EPROM, dd.mm.yyyy) and the
    // number of outputs (?AMAX, cam tracks). Empty / 0: the profile's.
    QByteArray epromDate;
    int outputs = 0;
    SimFaultSettings faults;
    QList<int> deadDevices;  // devices of the line that never answer (cambench-sim --dead-devices)

    Framing effectiveFraming() const {
        return framing ? *framing : (devices.size() > 1 ? Framing::Multiuser : Framing::Standard);
    }
    // 10 (8N1), 11 for 3964R e38 (8E1).
    int bitsPerByte() const;
    // "Standard", "Multiuser", "3964R n96", ...
    QString protocolName() const;
};

// Sets the framing, table variant or Cam-BUS of a registry id ("standard",
// "multiuser", "3964r-n96", "3964r-e38", "cambus"); false for another id.
bool applySimProtocol(SimPortConfig& config, const QString& protocol);

// Keys: devices, display and pcanswer (Cam-BUS), framing (standard|multiuser), protocol
// (standard|multiuser| 3964r-n96|3964r-e38), baud, corrupt (damaged replies), drop (lost replies),
// ignore (lost requests), dropfirst (the first reply to a request starting so is lost, e.g.
// !EE0000), nak, lostdle, collision, linkfaults (corrupt, nak, lostdle and collision at once),
// delay, seed, throttle (0|1), fill, analogue (0..14 analogue outputs), dead (0|1), eprom
// (the firmware date dd.mm.yyyy), outputs (1..64). The baud rate
// defaults to `serial.baud`. Fails with Usage on an unknown key or a bad value.
Result<SimPortConfig> parseSimPort(const QString& port, const SerialSettings& serial);

// Device numbers "0,5" -> {0, 5}; each 0..63, no duplicates.
Result<QList<int>> parseDeviceList(const QString& text);

// Another identity (cambench-sim --eprom/--outputs, sim:eprom=;outputs=):
// a firmware date "dd.mm.yyyy" and 1..64 outputs; false with the expected
// form in `expected` otherwise.
bool applyEpromDate(SimPortConfig& config, const QString& date, QString* expected);
bool applyOutputs(SimPortConfig& config, const QString& outputs, QString* expected);

}  // namespace cambench::comm
