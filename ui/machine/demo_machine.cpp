#include "demo_machine.h"

#include <QFile>
#include <QFileInfo>

namespace cambench {

namespace {

Result<MachineFile> readFrom(const QString& path, const QString& where) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return Error::invalidData(
            QStringLiteral("Machine file %1: cannot be read (%2).").arg(where, file.errorString()));
    return parseMachineFile(file.readAll(), where);
}

}  // namespace

Result<MachineFile> demoMachineFile() {
    // The resource of ui/CMakeLists.txt (docs/demo-machine.json).
    return readFrom(QStringLiteral(":/cambench/demo-machine.json"),
                    QStringLiteral("demo-machine.json"));
}

Result<MachineFile> readMachineFile(const QString& path) {
    return readFrom(path, QFileInfo(path).fileName());
}

}  // namespace cambench
