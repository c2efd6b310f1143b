#include "cambus_bench.h"

#include "bench_process.h"
#include "bench_run.h"
#include "tests/e2e/child_process.h"

#include "comm/camcon/cambus/cambus_camcon.h"
#include "comm/sim/camcon/cambus/sim_cambus_line.h"
#include "comm/sim/camcon/sim_demo.h"
#include "comm/sim/camcon/sim_port_config.h"
#include "comm/sim/sim_transport.h"

#include <QElapsedTimer>
#include <QRegularExpression>
#include <QTemporaryDir>
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

struct CliResult {
    int exitCode = -1;
    double seconds = 0;
    QString err;
};

CliResult runCli(const QStringList& args) {
    QProcess cli;
    cli.setProgram(QStringLiteral(CAMBENCH_CLI_EXE));
    cli.setArguments(args);
    e2e::endWithThisTest(cli);
    QElapsedTimer timer;
    timer.start();
    cli.start();
    CliResult result;
    if (cli.waitForFinished(-1) && cli.exitStatus() == QProcess::NormalExit)
        result.exitCode = cli.exitCode();
    result.seconds = timer.nsecsElapsed() / 1e9;
    result.err = QString::fromUtf8(cli.readAllStandardError()).trimmed();
    return result;
}

}  // namespace

void benchCamBusAnswers() {
    QTextStream out(stdout);
    QTemporaryDir dir;
    QProcess sim;
    const QString port = startSim(
        sim, {QStringLiteral("--protocol"), QStringLiteral("cambus"), QStringLiteral("--devices"),
              QStringLiteral("3,7"), QStringLiteral("--display"), QStringLiteral("12"),
              QStringLiteral("--verbose")});
    const QStringList line{QStringLiteral("--port"), port, QStringLiteral("--protocol"),
                           QStringLiteral("cambus")};
    const QString image = dir.filePath(QStringLiteral("b3.json"));
    const QList<QStringList> commands{
        {QStringLiteral("--device"), QStringLiteral("3"), QStringLiteral("backup"),
         QStringLiteral("-o"), image},
        {QStringLiteral("--device"), QStringLiteral("3"), QStringLiteral("restore"), image,
         QStringLiteral("--no-safety-backup")},
        {QStringLiteral("--device"), QStringLiteral("3"), QStringLiteral("verify"), image},
        {QStringLiteral("--device"), QStringLiteral("7"), QStringLiteral("info")}};
    out << "| cambench-cli --protocol cambus (38400 baud, T = 10 ms, display 12 polling 3) | "
           "exit | time |\n| --- | ---: | ---: |\n";
    for (const QStringList& command : commands) {
        const CliResult run = runCli(line + command);
        out << QStringLiteral("| %1 | %2 | %3 s |\n")
                   .arg(command.join(QLatin1Char(' ')).replace(image, QStringLiteral("b3.json")))
                   .arg(run.exitCode)
                   .arg(run.seconds, 0, 'f', 2);
        if (run.exitCode != 0) out << "\n    " << run.err << "\n\n";
        out.flush();
    }
    sim.terminate();
    sim.waitForFinished(10000);
    const QString log = QString::fromUtf8(sim.readAllStandardError());
    const QRegularExpression summary(QStringLiteral("Cam-BUS: the PC answered [^\n]*"));
    const QRegularExpressionMatch match = summary.match(log);
    out << "\nthe simulated users' view of the PC's answers: "
        << (match.hasMatch() ? match.captured(0)
                             : QStringLiteral("(no summary from the simulator)"))
        << "\n";
}

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
