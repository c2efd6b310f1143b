#pragma once

#include <QString>

namespace cambench::comm {

// Text of a device error number (manual 4.6.1), in English; the UI
// translates it through the "DeviceErrors" context.
QString deviceErrorText(qint32 code);

}  // namespace cambench::comm
