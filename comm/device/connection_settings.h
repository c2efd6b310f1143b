#pragma once

#include <QString>

namespace cambench::comm {

// Serial line settings; every one QSerialPort offers.
struct SerialSettings {
    int baud = 9600;
    int dataBits = 8;
    char parity = 'N';       // 'N', 'E', 'O', 'S', 'M'
    int stopBits = 1;        // 1 or 2 (3 = one and a half)
    char flowControl = 'N';  // 'N' none, 'H' RTS/CTS, 'S' XON/XOFF
    bool dtr = true;         // failing to set DTR/RTS (pty) must not abort a connection
    bool rts = true;
    // Breaks travel in the byte stream as PARMRK marks them (break_marks.h):
    // a real port reads with PARMRK and turns a written FF 00 00 into a
    // real break; a pseudo-terminal carries the marks as they are. Set by
    // a protocol that needs breaks (Cam-BUS), not by the user.
    bool inBandBreaks = false;
};

// How to reach the device. `port` is a device path or name (/dev/ttyUSB0,
// COM3, any pty path), "tcp://host:port" (serial device servers) or "sim".
struct ConnectionSettings {
    QString port = QStringLiteral("sim");
    SerialSettings serial;
    // The protocol id the PC speaks ("standard", "3964r-n96"): a transport
    // ignores it, but a simulated device on the far side answers in it.
    // Empty: the simulated device is what the port names (Detect: a
    // device that followed each probe would answer every one).
    QString protocol;
};

}  // namespace cambench::comm
