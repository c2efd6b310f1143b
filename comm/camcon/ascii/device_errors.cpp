#include "device_errors.h"

#include <QCoreApplication>

namespace cambench::comm {

namespace {

struct ErrorText {
    qint32 low;  // the numbers low..high share a text (the manual's -21..-39)
    qint32 high;
    const char* text;
};

// Manual 4.6.1, each with what a person at the machine can do about it.
// QT_TRANSLATE_NOOP marks the texts for lupdate.
const ErrorText kManualErrors[] = {
    {-10, -10,
     QT_TRANSLATE_NOOP("DeviceErrors",
                       "The device's RAM is too small for this setting (manual: \"RAM zu klein für "
                       "Einstellung\"). Choose a smaller value, e.g. fewer PLC elements.")},
    {-12, -12,
     QT_TRANSLATE_NOOP("DeviceErrors",
                       "The dead-time compensation value is too large. Enter at most the device's "
                       "maximum dead time (cambench-cli info: maxDeadTime).")},
    {-20, -20,
     QT_TRANSLATE_NOOP("DeviceErrors",
                       "The device's EEPROM is defective. Back up what can still be read and have "
                       "the device repaired.")},
    {-39, -21,
     QT_TRANSLATE_NOOP("DeviceErrors",
                       "The device's EEPROM is full. Delete cams or programs that are no longer "
                       "needed, then write again.")},
    {-40, -40,
     QT_TRANSLATE_NOOP("DeviceErrors",
                       "Checksum error in the device's EEPROM: the stored data may be damaged. "
                       "Restore a backup or enter the data again.")},
    {-41, -41,
     QT_TRANSLATE_NOOP("DeviceErrors",
                       "Block 0000 of the restore (!EE) has the wrong length: the image does not "
                       "suit this device. Use an image taken from this kind of device.")},
    {-42, -42,
     QT_TRANSLATE_NOOP("DeviceErrors",
                       "The device cannot erase its EEPROM. Switch it off and on and restore "
                       "again; if that fails too, the device needs repair.")},
    {-43, -43,
     QT_TRANSLATE_NOOP("DeviceErrors",
                       "The restore (!EE) sent the blocks in the wrong block number order. Restore "
                       "again from the start; if it happens again, the image file is damaged.")},
    {-44, -44,
     QT_TRANSLATE_NOOP("DeviceErrors",
                       "The CamCon cannot start after the restore (!EE): the data do not suit it. "
                       "Restore the safety backup or an image taken from this device.")},
    {-45, -45,
     QT_TRANSLATE_NOOP("DeviceErrors",
                       "A block of the restore (!EE) has the wrong length: the image file is "
                       "damaged. Restore another image.")},
    {-46, -46,
     QT_TRANSLATE_NOOP("DeviceErrors",
                       "The device did not receive the data completely: the line lost bytes. "
                       "Check the cable and the baud rate, then try again.")},
};

const ErrorText* find(qint32 code) {
    for (const ErrorText& entry : kManualErrors) {
        if (code >= entry.low && code <= entry.high) return &entry;
    }
    return nullptr;
}

QString translated(const char* text) {
    return QCoreApplication::translate("DeviceErrors", text);
}

}  // namespace

bool manualExplains(qint32 code) {
    return find(code) != nullptr;
}

QString deviceErrorText(qint32 code) {
    if (const ErrorText* entry = find(code)) return translated(entry->text);
    if (code == -1) {
        return translated(QT_TRANSLATE_NOOP(
            "DeviceErrors",
            "The manual gives no meaning for error -1 (it lists it only as \"unknown error\"). "
            "The device refused the request: check that the values lie within its limits and "
            "that the item exists."));
    }
    return translated(QT_TRANSLATE_NOOP("DeviceErrors",
                                        "The manual gives no meaning for error %1. Note the "
                                        "number and the command and ask the device's supplier."))
        .arg(code);
}

}  // namespace cambench::comm
