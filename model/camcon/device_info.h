#pragma once

#include "model/device_identity.h"

#include <QList>
#include <QString>

namespace cambench {

// Identity and capacities of a device (manual 5.4.7 and the counts of 5.3.6).
// Filled by `info`, stored in project and EEPROM image headers, and used to
// validate edits offline.
struct DeviceInfo {
    QString epromDate;               // ?EPROM, e.g. "11.10.1994"
    int deviceNumber = 0;            // ?GNR (0..63)
    int protocol = 1;                // ?GSIO: 0 Cam-BUS, 1 Standard, 2 Multiuser, 3 S5-L1, 4 3964R
    int outputs = 32;                // ?AMAX (multiple of 8, 8..200)
    int inputs = 16;                 // ?EMAX (multiple of 8, 0..200)
    int deadTimeOutputs = 32;        // ?GTZKANZ
    int programs = 16;               // ?GPRGMAX: programs 0..programs-1
    qint32 minPosition = 0;          // ?IMIN
    qint32 maxPosition = 359;        // ?IMAX
    qint32 maxDeadTime = 9999;       // ?GTZKMAX, 0.1 ms steps
    int cpuClock = 0;                // ?GCPUCLK: 0 = 16.7 MHz, 1 = 25.2 MHz
    int temperature = 255;           // ?GTEMP in deg C, 255 = no sensor
    qint32 freeCams = 0;             // ?MEEFREE
    qint32 programmedCams = 0;       // ?MEENOCK
    qint32 programmedDeadTimes = 0;  // ?MEETZK
    qint32 ramSize = 0;              // ?MRAMMAX
    qint32 ramFree = 0;              // ?MRAMFREE
    qint32 serialEepromSize = 0;     // ?MEES
    qint32 parallelEepromSize = 0;   // ?MPEE

    friend bool operator==(const DeviceInfo& a, const DeviceInfo& b);
};

// What tells two CamCons apart (the protocols offer no serial number): the
// EPROM date, the device number, the capacities and the memory sizes -
// nothing that a write of cams, programs or settings changes. A restore
// compares it with the image's (comm/camcon/usecases/backup_restore.h).
DeviceIdentity camConIdentity(const DeviceInfo& info);

// Whether `now` (read on a connect) is the device `before` was read from.
// The identity (camConIdentity) must agree; with `compareContents`, also the cheap fingerprint of
// what it holds (programmed cams, free cams, programmed dead times), which tells apart two devices
// of the same kind and a device changed by someone else. Callers skip the fingerprint after their
// own writes changed it. Temperature and free RAM change by themselves and are not compared.
bool sameDevice(const DeviceInfo& before, const DeviceInfo& now, bool compareContents);

// What `status` shows (manual 5.1 and the provisional 5.1.6..5.1.8).
struct DeviceStatus {
    int errorState = 0;     // ?ERR: 0 ok, 1..3 actual-value error, 4 output error, 0xFF EEPROM
    qint32 position = 0;    // ?IGWG (actual-value units)
    QString positionText;   // ?IFGWG formatted
    qint32 speed = 0;       // ?BSPEED raw
    QString speedText;      // ?SPEED formatted
    int activeProgram = 0;  // ?PAU
    QList<bool> outputs;    // ?ATAB, index 0 = output 1
    QList<bool> inputs;     // ?ETAB, index 0 = input 1
};

}  // namespace cambench
