#pragma once

#include "model/device_identity.h"
#include "model/result.h"

#include <QString>

namespace cambench::comm {
class DeviceConnection;
}

namespace cambench::usecases {

// Who answers on a device's line (issue 36, "always the right devices"),
// with queries only: whether a device of the connection's family
// identifies itself, what tells it apart, and - when none does - whether
// anything answered at all (another device on the line) or nothing did.
struct LineAnswer {
    bool identified = false;
    QString text;             // identify()'s line, when identified
    DeviceIdentity identity;  // readIdentity(), when identified and asked for
    // Not identified, but the device answered the last request with bytes
    // of its own (a device of another family, or another protocol).
    bool heardOther = false;
    QString problem;  // why it did not identify itself
};

// `withIdentity`: also reads readIdentity() (a few more queries). Never
// fails but for a cancel (Cancelled); a device that does not identify
// itself is an answer (identified false), not an error.
Result<LineAnswer> lineAnswer(comm::DeviceConnection& device, bool withIdentity);

}  // namespace cambench::usecases
