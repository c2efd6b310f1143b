#pragma once

#include <QByteArray>

namespace cambench::comm {

// Identity, capacities and timing of one simulated CamCon. The defaults are
// a small CamCon DC with the manual's example EPROM date.
struct SimProfile {
    QByteArray epromDate = "11.10.1994";  // ?EPROM and the :Z reply
    int outputs = 32;                     // ?AMAX default, also the number of cam tracks
    int inputs = 16;                      // ?EMAX default
    int programs = 16;                    // ?GPRGMAX: programs 0..programs-1
    qint32 minPosition = 0;               // ?IMIN
    qint32 maxPosition = 359;             // ?IMAX
    qint32 maxDeadTime = 9999;            // ?GTZKMAX, 0.1 ms steps
    int cpuClock = 1;                     // ?GCPUCLK: 1 = 25.2 MHz
    int temperature = 38;                 // ?GTEMP in deg C
    qint32 camCapacity = 8000;            // cams the EEPROM holds: ?MEEFREE = this - ?MEENOCK
    qint32 ramSize = 131072;              // ?MRAMMAX
    qint32 serialEepromSize = 65536;      // ?MEES
    qint32 parallelEepromSize = 131072;   // ?MPEE
    int userTextLines = 8;                // ?BTXT lines 0..n-1
    int plcTexts = 16;                    // ?ETXT messages 0..n-1
    int analogChannels = 14;              // ?AMODE channels 0..13
    int maxUsers = 32;
    int protocol = 1;  // ?GSIO default: 1 Standard, 2 Multiuser

    // The simulated axis turns at this many actual-value units per second
    // (0 = standing still).
    // One turn in 10 s: slow enough that a 250 ms trend shows a clean
    // sawtooth instead of aliasing, fast enough to see the outputs switch.
    double unitsPerSecond = 36.0;

    // Delays in milliseconds before a reply leaves the device.
    int processingDelayMs = 2;  // every request
    int clearDelayMs = 1500;    // !CA (a real device takes up to 2 minutes)
    int eraseDelayMs = 500;     // !EE0000 erases the EEPROM first

    // Fault option: the EEPROM cannot be erased (!EE0000 answers -42).
    bool eraseFails = false;
};

}  // namespace cambench::comm
