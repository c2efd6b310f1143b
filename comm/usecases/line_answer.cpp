#include "line_answer.h"

#include "machine_backup.h"

#include "comm/device/device_connection.h"

namespace cambench::usecases {

Result<LineAnswer> lineAnswer(comm::DeviceConnection& device, bool withIdentity) {
    LineAnswer answer;
    if (withIdentity) {
        // Who it is as a machine backup asks (identify, then readIdentity).
        const Result<DeviceAnswer> found = whoAnswers(device);
        if (found) {
            answer.identified = true;
            answer.text = found->text;
            answer.identity = found->identity;
            return answer;
        }
        if (found.error().kind == ErrorKind::Cancelled) return found.error();
        answer.problem = found.error().message;
    } else {
        const Result<QString> text = device.identify();
        if (text) {
            answer.identified = true;
            answer.text = *text;
            return answer;
        }
        if (text.error().kind == ErrorKind::Cancelled) return text.error();
        answer.problem = text.error().message;
    }
    // Bytes came back, yet not the family's answer: someone else is on the
    // line. (A bus backend counts only its device's own frames.)
    answer.heardOther = device.engine().lastCallHeardDevice();
    return answer;
}

}  // namespace cambench::usecases
