#include "sim_bench.h"

#include <QtGlobal>

namespace cambench::tests {

using namespace comm;

SimBench::SimBench(QList<int> devices, std::optional<Framing> framing)
    : SimBench([&] {
          SimPortConfig config;
          config.devices = devices;
          config.framing = framing;
          return config;
      }()) {}

SimBench::SimBench(SimPortConfig config) {
    config.throttle = false;
    transport = std::make_unique<SimTransport>(camConSimulatedLine(config));
    const Status opened = transport->open();
    if (!opened) qFatal("%s", qPrintable(opened.error().message));
    AsciiSettings settings;
    settings.framing = config.effectiveFraming();
    settings.device = config.devices.first();
    // Short: a dead device is declared dead quickly (a hang bound, not a
    // performance limit).
    settings.timeoutMs = 200;
    settings.longTimeoutMs = 5000;
    link = std::make_unique<AsciiLink>(*transport, settings);
    client = std::make_unique<AsciiCamCon>(*link);
    injections().setLogging(true);
}

DeviceInfo SimBench::info() {
    const Result<DeviceInfo> read = client->readInfo();
    if (!read) qFatal("%s", qPrintable(read.error().message));
    return *read;
}

int SimBench::commandsSent() {
    const int commands = injections().commands();
    injections().clearLog();
    return commands;
}

}  // namespace cambench::tests
