#pragma once

#include "transport.h"

#include <memory>

namespace cambench::comm {

// The transport `connection.port` names: "sim" or "sim:<options>" the
// in-process simulator, "tcp://host:port" a serial device server, anything
// else a serial port opened as given. Not opened yet. Fails with a Usage
// error when the name cannot be used.
Result<std::unique_ptr<Transport>> makeTransport(const ConnectionSettings& connection);

}  // namespace cambench::comm
