#pragma once

#include <QList>
#include <QString>

namespace cambench {

// A key-assignment entry (manual 5.4.1). The number is the access code and a
// secret: never log or print it unmasked (use maskedNumber()).
struct User {
    enum Right : quint32 {
        ProgramSelection = 1u << 0,
        Programming = 1u << 1,
        SystemSettings = 1u << 2,
        DeviceConfiguration = 1u << 3,
        PlcMenu = 1u << 5,
        AllOutputs = 1u << 6,
        UserMenu = 1u << 7,
    };

    QString name;              // up to 21 characters
    QString number;            // up to 5 characters
    QList<bool> outputAccess;  // 256 entries, index 0 = output 1
    bool allOutputs = false;
    quint32 rights = 0;

    QString maskedNumber() const { return number.isEmpty() ? QString() : QStringLiteral("*****"); }
    friend bool operator==(const User& a, const User& b) {
        return a.name == b.name && a.number == b.number && a.outputAccess == b.outputAccess &&
               a.allOutputs == b.allOutputs && a.rights == b.rights;
    }
};

}  // namespace cambench
