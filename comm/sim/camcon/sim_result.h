#pragma once

#include "comm/camcon/ascii/fields.h"

#include <functional>
#include <utility>

namespace cambench::comm {

// What a command handler decided; the device turns it into a reply body
// with the codec of the command's catalogue entry.
struct SimResult {
    enum Kind { Data, Ok, Error, NoReply };
    Kind kind = Ok;
    Fields fields;    // Data
    qint32 code = 0;  // Error
    int delayMs = 0;  // extra work before the reply (!CA, erasing the EEPROM)

    static SimResult data(Fields fields) { return {Data, std::move(fields), 0, 0}; }
    static SimResult ok(int delayMs = 0) { return {Ok, {}, 0, delayMs}; }
    static SimResult error(qint32 code) { return {Error, {}, code, 0}; }
    static SimResult none() { return {NoReply, {}, 0, 0}; }
    // 0 = Ok, anything else an error number.
    static SimResult okOr(qint32 code) { return code == 0 ? ok() : error(code); }
};

using SimHandler = std::function<SimResult(const Fields& request)>;

}  // namespace cambench::comm
