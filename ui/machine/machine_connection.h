#pragma once

#include "comm/device/connection_settings.h"
#include "comm/device/protocol_settings.h"
#include "model/machine/machine_file.h"
#include "model/result.h"

namespace cambench {

// How the GUI reaches one device of a machine file: its line and its
// protocol's settings, read from the device's options as the command line
// reads them: "port", "protocol" (or the family's default, or its first
// protocol that takes the options given), "baud", and the options the
// protocol declares (comm/device/protocol_options.h).
struct MachineConnection {
    comm::ConnectionSettings connection;
    comm::ProtocolSettingsPtr protocol;  // never null
};

// An unknown family or protocol, a protocol of another family, an option
// the protocol does not take or a value outside its range is refused naming
// the device ("feed: ...") before any line is opened.
Result<MachineConnection> machineConnection(const MachineDevice& device);

// The machine file's entry for a connection the GUI holds (New machine:
// the connection of the window it was started from).
MachineDevice machineDeviceFor(const QString& name, const comm::ConnectionSettings& connection,
                               const comm::ProtocolSettings& protocol);

}  // namespace cambench
