#include "plc_network.h"

#include <QCoreApplication>

#include <algorithm>

namespace cambench {

bool PlcNetwork::isEmpty() const {
    return value == 0 && reset == 0 &&
           std::all_of(symbols.begin(), symbols.end(), [](quint16 s) { return s == 0; });
}

QString PlcNetwork::describe(int area, int number) {
    const char* names = "OPMX";
    const int index = area - O;
    const QChar letter = index >= 0 && index < 4 ? QChar::fromLatin1(names[index]) : QChar(u'?');
    return QCoreApplication::translate("cambench::model", "PLC network %1%2")
        .arg(letter)
        .arg(number);
}

}  // namespace cambench
