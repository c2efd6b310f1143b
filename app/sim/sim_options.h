#pragma once

#include "comm/sim/simulator_registry.h"

#include <QCommandLineParser>
#include <QString>

#include <optional>

namespace cambench {

// cambench-sim's command line: what every family shares and where to serve.
struct SimCommandLine {
    comm::SimHostOptions shared;
    std::optional<quint16> tcpPort;
    bool verbose = false;
};

// Every option of cambench-sim: the shared ones and each family's own.
void addSimOptions(QCommandLineParser& parser);

// The shared options of `parser` into `options`; empty on success, else
// what is wrong.
QString readSharedSimOptions(const QCommandLineParser& parser, SimCommandLine& options);

}  // namespace cambench
