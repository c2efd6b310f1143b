#pragma once

#include <QCoreApplication>
#include <QLocale>
#include <QString>

namespace cambench {

// A time the device keeps in 0.1 ms steps (dead times), as a person reads it
// in the application's language: "12.5 ms", "12,5 ms".
inline QString millisecondsText(qint32 tenths) {
    return QCoreApplication::translate("cambench", "%1 ms")
        .arg(QLocale().toString(tenths / 10.0, 'f', 1));
}

}  // namespace cambench
