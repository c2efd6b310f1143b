#include "program_read.h"

#include <QCoreApplication>

namespace cambench::usecases {

Status checkProgramNumber(int number, const DeviceInfo& device) {
    if (number >= 0 && number < device.programs) return success();
    if (device.programs <= 0)
        return Error::invalidData(QCoreApplication::translate(
                                      "cambench::usecases",
                                      "program %1 does not exist: the device reports no programs; "
                                      "read its identity again or check the connection")
                                      .arg(number));
    return Error::invalidData(
        QCoreApplication::translate("cambench::usecases",
                                    "program %1 does not exist on the device (it has programs "
                                    "0 to %2): choose one of those")
            .arg(number)
            .arg(device.programs - 1));
}

Result<CamProgram> readProgram(comm::CamConDevice& connection, const DeviceInfo& device, int number,
                               const UseCaseProgress& progress) {
    if (const Status fits = checkProgramNumber(number, device); !fits) return fits.error();
    if (progress.cancelled()) return Error::cancelled();
    const QString text =
        QCoreApplication::translate("cambench::usecases", "reading program %1").arg(number);
    Result<CamProgram> read =
        connection.readProgram(number, device.outputs, progress.forDevice(text));
    if (!read) return read.error();
    CamProgram program = std::move(read).value();
    program.number = number;
    return program;
}

Result<ProgramRead> readIdentityAndProgram(comm::CamConDevice& connection, int number,
                                           const UseCaseProgress& progress) {
    const Result<DeviceInfo> device = connection.readInfo();
    if (!device) return device.error();
    Result<CamProgram> program = readProgram(connection, *device, number, progress);
    if (!program) return program.error();
    return ProgramRead{*device, std::move(program).value()};
}

}  // namespace cambench::usecases
