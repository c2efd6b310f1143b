#include "programming_program.h"

#include <QCoreApplication>

namespace cambench {

namespace {
const char* const kSelectModeKeys[] = {"slow", "direct", "at-value"};
}  // namespace

QString programmingSelectModeKey(int selectMode) {
    if (selectMode < 0 || selectMode > 2) return QStringLiteral("?");
    return QString::fromLatin1(kSelectModeKeys[selectMode]);
}

int programmingSelectModeFromKey(const QString& key) {
    for (int mode = 0; mode <= 2; ++mode) {
        if (key == QLatin1String(kSelectModeKeys[mode])) return mode;
    }
    return -1;
}

QStringList validateProgrammingProgram(const ProgrammingProgram& programming,
                                       const DeviceInfo& device) {
    QStringList problems;
    if (programming.program < 0 || programming.program >= device.programs) {
        problems.append(
            QCoreApplication::translate("cambench::model",
                                        "Programming program %1 does not exist (programs 0..%2).")
                .arg(programming.program)
                .arg(device.programs - 1));
    }
    if (programming.selectMode < 0 || programming.selectMode > 2) {
        problems.append(
            QCoreApplication::translate("cambench::model",
                                        "Programming program select mode %1 is unknown (0 slow, 1 "
                                        "direct, 2 at the actual value).")
                .arg(programming.selectMode));
    }
    if (programming.selectMode == 2 && (programming.switchValue < device.minPosition ||
                                        programming.switchValue > device.maxPosition)) {
        problems.append(
            QCoreApplication::translate("cambench::model",
                                        "Programming program switch value %1 is outside %2..%3.")
                .arg(programming.switchValue)
                .arg(device.minPosition)
                .arg(device.maxPosition));
    }
    return problems;
}

}  // namespace cambench
