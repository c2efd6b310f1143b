#include "compax3_read_objects.h"

#include <QCoreApplication>

namespace cambench::usecases {

Result<QList<Compax3Reading>> readCompax3Objects(comm::Compax3Device& device,
                                                 const QList<Compax3ObjectId>& ids, bool hex,
                                                 const UseCaseProgress& progress) {
    QList<Compax3Reading> readings;
    for (const Compax3ObjectId& id : ids) {
        if (progress.cancelled()) return Error::cancelled();
        const Result<QString> value = device.readObject(id, hex);
        if (!value && value.error().kind != ErrorKind::DeviceError) return value.error();
        readings << Compax3Reading{id, value ? *value : QString(), value ? Error{} : value.error()};
        progress.report(readings.size(), ids.size(),
                        QCoreApplication::translate("cambench::usecases", "Reading objects"));
    }
    return readings;
}

Error firstCompax3Refusal(const QList<Compax3Reading>& readings) {
    for (const Compax3Reading& reading : readings)
        if (reading.refused()) return reading.refusal;
    return {};
}

}  // namespace cambench::usecases
