#include "cambus_bench.h"

#include "bench_run.h"

#include "comm/camcon/cambus/cambus_camcon.h"
#include "comm/sim/camcon/cambus/sim_cambus_line.h"
#include "comm/sim/camcon/sim_demo.h"
#include "comm/sim/camcon/sim_port_config.h"
#include "comm/sim/sim_transport.h"

#include <QTextStream>

#include <algorithm>
#include <cstdio>

namespace cambench::bench {

namespace {

using namespace cambench::comm;

constexpr int kBaud = 38400;

struct Bus {
    SimTransport transport;
    SimCamBusLine* line;
    std::unique_ptr<CamBusCamCon> camCon;
};

std::unique_ptr<Bus> makeBus() {
    SimPortConfig config;
    config.devices = {3, 7};
    config.displays = {12, 13};
    config.baud = kBaud;
    config.fill = 8;  // 8 cams on every track: a backup of more than 32 KiB
    applySimProtocol(config, QStringLiteral("cambus"));
    SimulatedLine simulated{makeSimEndpoint(config), SimPacer(kBaud, true, 10),
                            QStringLiteral("simulated Cam-BUS")};
    auto* line = static_cast<SimCamBusLine*>(simulated.endpoint.get());
    auto bus = std::unique_ptr<Bus>(new Bus{SimTransport(std::move(simulated)), line, nullptr});
    openOrExit(bus->transport);
    AsciiSettings ascii;
    ascii.device = 3;
    LineTiming timing;
    timing.baud = kBaud;
    CamBusStationConfig station;
    station.baud = kBaud;
    bus->camCon = std::make_unique<CamBusCamCon>(bus->transport, ascii, timing, station, nullptr);
    return bus;
}

void printRow(const QString& what, const Run& run, qint64 ownBytes, const SimCamBusLine& line) {
    const double limit = double(ownBytes) * 10 / kBaud;
    qint64 pause = 0;
    for (int i = 0; i < line.displayCount(); ++i)
        pause = std::max(pause, line.display(i)->longestPauseMs());
    QTextStream(stdout) << QStringLiteral("| %1 | %2 | %3 | %4 s | %5 s | %6 | %7 ms |\n")
                               .arg(what)
                               .arg(run.requests)
                               .arg(ownBytes)
                               .arg(run.seconds, 0, 'f', 2)
                               .arg(limit, 0, 'f', 2)
                               .arg(run.seconds / limit, 0, 'f', 2)
                               .arg(pause);
}

void resetPauses(SimCamBusLine& line) {
    for (int i = 0; i < line.displayCount(); ++i) line.display(i)->resetPauses(-1);
}

}  // namespace

void benchCamBus() {
    QTextStream(stdout) << "| operation (CamCon 3, 38400 baud, displays 12 and 13 polling) | "
                           "requests | PC's own wire B | time | wire limit | ratio | displays' "
                           "longest pause |\n"
                           "| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    std::unique_ptr<Bus> bus = makeBus();
    CamBusBackend& backend = bus->camCon->bus();
    // Joining (an initialisation phase) is not part of the work measured.
    qint64 before = backend.ownTrafficBytes();
    Run join = timeWork(bus->camCon->engine(), [&] {
        const Result<DeviceInfo> info = bus->camCon->readInfo();
        return info ? success() : Status(info.error());
    });
    QTextStream(stdout) << QStringLiteral(
                               "| joining the bus and ?-reading the identity | %1 | %2 | "
                               "%3 s | | | |\n")
                               .arg(join.requests)
                               .arg(backend.ownTrafficBytes() - before)
                               .arg(join.seconds, 0, 'f', 2);
    resetPauses(*bus->line);
    before = backend.ownTrafficBytes();
    Run backup = timeWork(bus->camCon->engine(), [&] {
        const Result<EepromImage> image = bus->camCon->backup();
        return image ? success() : Status(image.error());
    });
    printRow(QStringLiteral("EEPROM backup"), backup, backend.ownTrafficBytes() - before,
             *bus->line);
    resetPauses(*bus->line);
    before = backend.ownTrafficBytes();
    Run program = timeWork(bus->camCon->engine(), [&] {
        const Result<CamProgram> read = bus->camCon->readProgram(0, 32);
        return read ? success() : Status(read.error());
    });
    printRow(QStringLiteral("program 0 read (32 tracks x 8 cams)"), program,
             backend.ownTrafficBytes() - before, *bus->line);
}

}  // namespace cambench::bench
