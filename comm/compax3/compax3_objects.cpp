#include "compax3_objects.h"

#include <QCoreApplication>

namespace cambench::comm {

QList<Compax3StatusBit> compax3StatusBits(quint16 word) {
    QList<Compax3StatusBit> bits;
    for (int i = 0; i < 8; ++i)
        bits << Compax3StatusBit{i,
                                 QCoreApplication::translate("cambench::comm", "input I%1").arg(i),
                                 bool(word & (1u << i))};
    const char* names[] = {
        QT_TRANSLATE_NOOP("cambench::comm", "no error"),
        QT_TRANSLATE_NOOP("cambench::comm", "position reached"),
        QT_TRANSLATE_NOOP("cambench::comm", "powerless"),
        QT_TRANSLATE_NOOP("cambench::comm", "powered standstill"),
        QT_TRANSLATE_NOOP("cambench::comm", "zero known"),
        QT_TRANSLATE_NOOP("cambench::comm", "PSB0"),
        QT_TRANSLATE_NOOP("cambench::comm", "PSB1"),
        QT_TRANSLATE_NOOP("cambench::comm", "PSB2"),
    };
    for (int i = 8; i < 16; ++i)
        bits << Compax3StatusBit{i, QCoreApplication::translate("cambench::comm", names[i - 8]),
                                 bool(word & (1u << i))};
    return bits;
}

QString compax3LastErrorText(int code) {
    const QString hex = compax3HexText(code, 4);
    switch (code) {
        case 1:
            return QCoreApplication::translate("cambench::comm", "no error");
        case 0x4310:
            return QCoreApplication::translate("cambench::comm", "motor temperature (%1)").arg(hex);
        case 0x7320:
            return QCoreApplication::translate("cambench::comm", "following error (%1)").arg(hex);
        case 0x7323:
            return QCoreApplication::translate("cambench::comm", "end limit + (%1)").arg(hex);
        case 0x7324:
            return QCoreApplication::translate("cambench::comm", "end limit − (%1)").arg(hex);
        case 0x7327:
            return QCoreApplication::translate("cambench::comm",
                                               "direction change while moving (%1)")
                .arg(hex);
        default:
            return QCoreApplication::translate("cambench::comm",
                                               "error %1 (%2): see the drive's manual")
                .arg(code)
                .arg(hex);
    }
}

}  // namespace cambench::comm
