#pragma once

#include <QByteArray>

namespace cambench::comm {

// One reply as it leaves a simulated device: wire bytes and how long the
// device works on the request before the first byte goes out.
struct SimOutput {
    QByteArray bytes;
    int delayMs = 0;
};

}  // namespace cambench::comm
