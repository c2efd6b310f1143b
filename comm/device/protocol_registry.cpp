#include "protocol_registry.h"

#include <QStringList>

namespace cambench::comm {

ProtocolRegistry& ProtocolRegistry::instance() {
    static ProtocolRegistry registry;
    return registry;
}

LineTiming lineTimingFor(const SerialSettings& serial) {
    LineTiming line;
    line.baud = serial.baud;
    const int parity = serial.parity == 'N' ? 0 : 1;
    const int stop = serial.stopBits == 1 ? 1 : 2;
    line.bitsPerByte = 1 + serial.dataBits + parity + stop;
    return line;
}

}  // namespace cambench::comm
