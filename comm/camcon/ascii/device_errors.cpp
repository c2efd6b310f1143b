#include "device_errors.h"

#include <QCoreApplication>

namespace cambench::comm {

QString deviceErrorText(qint32 code) {
    // QT_TRANSLATE_NOOP marks the texts for lupdate; the UI translates them.
    const char* text = nullptr;
    switch (code) {
        case -1:
            text = QT_TRANSLATE_NOOP("DeviceErrors", "Unknown error.");
            break;
        case -10:
            text = QT_TRANSLATE_NOOP("DeviceErrors", "RAM too small for this setting.");
            break;
        case -12:
            text = QT_TRANSLATE_NOOP("DeviceErrors", "Dead time compensation value too large.");
            break;
        case -20:
            text = QT_TRANSLATE_NOOP("DeviceErrors", "EEPROM defective.");
            break;
        case -40:
            text = QT_TRANSLATE_NOOP("DeviceErrors", "Checksum error in the EEPROM.");
            break;
        case -41:
            text = QT_TRANSLATE_NOOP("DeviceErrors", "Wrong length of block 0000 in !EE.");
            break;
        case -42:
            text = QT_TRANSLATE_NOOP("DeviceErrors", "The EEPROM cannot be erased.");
            break;
        case -43:
            text = QT_TRANSLATE_NOOP("DeviceErrors", "Wrong block number order in !EE.");
            break;
        case -44:
            text = QT_TRANSLATE_NOOP("DeviceErrors", "The CamCon cannot start after !EE.");
            break;
        case -45:
            text = QT_TRANSLATE_NOOP("DeviceErrors", "Wrong block length in !EE.");
            break;
        case -46:
            text = QT_TRANSLATE_NOOP("DeviceErrors", "Data reception incomplete.");
            break;
        default:
            if (code <= -21 && code >= -39)
                text = QT_TRANSLATE_NOOP("DeviceErrors", "EEPROM full.");
            break;
    }
    if (!text) return QStringLiteral("Unknown device error %1.").arg(code);
    return QString::fromLatin1(text);
}

}  // namespace cambench::comm
