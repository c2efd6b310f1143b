#pragma once

// Reading a list of objects, the one loop behind the Objects page, the
// Watch page, `c3 read` and `c3 watch`: a refusal is kept with its object
// and the rest is read on; a line failure ends the list.

#include "comm/compax3/compax3_device.h"
#include "comm/usecases/use_case_progress.h"

#include <QList>

namespace cambench::usecases {

// One object as read: its value, or the drive's refusal (kind DeviceError,
// the message holds the drive's "!xxxx").
struct Compax3Reading {
    Compax3ObjectId id;
    QString value;
    Error refusal;
    bool refused() const { return refusal.kind != ErrorKind::None; }
};

// `hex`: asks for hexadecimal answers ("$1A").
Result<QList<Compax3Reading>> readCompax3Objects(comm::Compax3Device& device,
                                                 const QList<Compax3ObjectId>& ids,
                                                 bool hex = false,
                                                 const UseCaseProgress& progress = {});

// The first refusal among `readings` (kind None when there is none).
Error firstCompax3Refusal(const QList<Compax3Reading>& readings);

}  // namespace cambench::usecases
