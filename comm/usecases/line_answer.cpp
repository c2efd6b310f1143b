#include "line_answer.h"

#include "comm/device/device_connection.h"

namespace cambench::usecases {

Result<LineAnswer> lineAnswer(comm::DeviceConnection& device, bool withIdentity) {
    LineAnswer answer;
    const Result<QString> text = device.identify();
    if (!text) {
        if (text.error().kind == ErrorKind::Cancelled) return text.error();
        answer.problem = text.error().message;
        // Bytes came back, yet not the family's answer: someone else is on
        // the line. (A bus backend counts only its device's own frames.)
        answer.heardOther = device.engine().lastCallHeardDevice();
        return answer;
    }
    answer.text = *text;
    if (withIdentity) {
        const Result<DeviceIdentity> identity = device.readIdentity();
        if (!identity) {
            if (identity.error().kind == ErrorKind::Cancelled) return identity.error();
            answer.problem = identity.error().message;
            answer.heardOther = device.engine().lastCallHeardDevice();
            return answer;
        }
        answer.identity = *identity;
    }
    answer.identified = true;
    return answer;
}

}  // namespace cambench::usecases
