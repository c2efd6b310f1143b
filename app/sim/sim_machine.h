#pragma once

#include "comm/sim/simulator_registry.h"
#include "model/result.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>
#include <vector>

namespace cambench {

// cambench-sim --machine FILE: every device of a machine file simulated in
// this one process, each on its own pseudo-terminal or TCP port, the file's
// shaft coupling the driving device's axis to the following one's position.
// The devices' ports are left out; their other options are read as
// cambench-sim reads its own, by their family's simulator.
class SimMachine {
public:
    // Reads the file and builds every device and the shaft; nothing is
    // served yet. `shared`: the faults and pacing of the command line, for
    // every device. An error names the file and the device.
    static Result<std::unique_ptr<SimMachine>> build(const QString& path,
                                                     const comm::SimHostOptions& shared);
    ~SimMachine();

    // Serves each device, on a pseudo-terminal or on TCP port `tcpBase` + i
    // (0: free ports); "NAME PATH" (or "NAME tcp://127.0.0.1:PORT") a device.
    Result<QStringList> serve(std::optional<quint16> tcpBase);

private:
    SimMachine() = default;

    QStringList m_names;
    std::vector<comm::SimulatedLine> m_lines;
    std::shared_ptr<comm::SimShaft> m_shaft;
    // After the lines: destroyed first, as they serve them.
    std::vector<std::unique_ptr<QObject>> m_servers;
};

}  // namespace cambench
