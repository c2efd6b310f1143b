#include "mc1_bench.h"

#include "bench_run.h"
#include "mc1_live_stop_bench.h"

#include "comm/mc1/mc1_controller.h"
#include "comm/sim/mc1/mc1_simulator.h"
#include "comm/sim/sim_transport.h"
#include "comm/traffic/traffic_entry.h"

#include <QElapsedTimer>
#include <QTextStream>

#include <cstdio>

namespace cambench::bench {

namespace {

using namespace cambench::comm;

constexpr int kBaud = 9600;
constexpr int kVariables = 1000;
constexpr int kRange = 32 * 1024;
// Single-byte reads take about 4 minutes for 32 KiB at 9600 baud: they are
// measured over 1 KiB, and the ratio is what compares.
constexpr int kSingleRange = 1024;

Run measure(Mc1Variant variant, const std::function<Status(Mc1Device&)>& work) {
    SimHostOptions shared;
    shared.throttle = true;
    SimTransport transport(mc1SimulatedLine(variant, kBaud, shared));
    openOrExit(transport);
    LineTiming line;
    line.baud = kBaud;
    Mc1Controller device(transport, Mc1Settings{variant, 0, 2, std::nullopt}, line);
    (void)device.ensureIdentified();
    return timeWork(device.engine(), [&] { return work(device); });
}

void printRow(const QString& what, Mc1Variant variant, const Run& run) {
    const double limit = double(run.wire) * 10 / kBaud;
    QTextStream(stdout) << QStringLiteral("| %1 | %2 | %3 | %4 | %5 s | %6 s | %7 |\n")
                               .arg(what, mc1VariantName(variant))
                               .arg(run.wire)
                               .arg(run.requests)
                               .arg(run.seconds, 0, 'f', 2)
                               .arg(limit, 0, 'f', 2)
                               .arg(run.seconds / limit, 0, 'f', 2);
}

Status readVariables(Mc1Device& device) {
    for (int n = 1; n <= kVariables; ++n)
        if (Result<qint64> value = device.readVariable(n); !value) return value.error();
    return success();
}

// An MC100's "memory" is its external RAM pages: 128 pages of 256 bytes.
Status readPages(Mc1Device& device, int bytes) {
    for (int page = 0; page * 256 < bytes; ++page)
        if (Result<QByteArray> got = device.readExternalPage(quint8(page)); !got)
            return got.error();
    return success();
}

// STOP of every axis of an MC200 V2 whose axes all jog: the time from
// pressing STOP to the last stop's acknowledgement, and the whole STOP
// with its read-backs after.
struct StopRun {
    double toLastAck = 0;
    double whole = 0;
    qint64 stopWire = 0;  // the stop telegrams and their answers
    int stops = 0;        // stop telegrams sent
    bool acknowledged = false;
};

StopRun measureStop(const QList<int>& axes, bool loseFirstAnswer) {
    SimHostOptions shared;
    shared.throttle = true;
    if (loseFirstAnswer) shared.faults.dropFirstReplyTo = QByteArray(1, char(0x9B));
    Mc1SimAxes simulated;
    simulated.axes = axes;
    SimTransport transport(mc1SimulatedLine(Mc1Variant::Mc200V2, kBaud, shared, 0, simulated));
    openOrExit(transport);
    LineTiming line;
    line.baud = kBaud;
    Mc1Controller device(transport, Mc1Settings{Mc1Variant::Mc200V2, 0, 2, std::nullopt}, line);
    // Found and moving before: what is measured is the STOP alone.
    for (int axis : axes) (void)device.axisCommand(axis, Mc1AxisCommand::JogPlus, 0);
    StopRun run;
    QElapsedTimer timer;
    bool answeringStop = false;
    device.engine().setTrafficSink([&](const TrafficEntry& entry) {
        if (entry.outgoing) {
            answeringStop = entry.bytes.startsWith(char(0x9B));
            if (answeringStop) ++run.stops;
        } else if (answeringStop) {
            run.toLastAck = timer.nsecsElapsed() / 1e9;
        }
        if (answeringStop) run.stopWire += entry.bytes.size();
    });
    timer.start();
    run.acknowledged = device.motionControl()->stopAllMotion().allAcknowledged();
    run.whole = timer.nsecsElapsed() / 1e9;
    return run;
}

void benchStop() {
    QTextStream(stdout) << "| STOP (MC200 V2, 9600 baud) | stops sent | stop wire B | to the last "
                           "ACK | wire limit | ratio | with read-backs | all acknowledged |\n| --- "
                           "| ---: | ---: | ---: | ---: | ---: | ---: | --- |\n";
    const QList<int> eight{1, 2, 3, 4, 5, 6, 7, 8};
    const QList<int> three{1, 2, 5};
    const struct {
        QString what;
        QList<int> axes;
        bool lose;
    } rows[] = {{QStringLiteral("8 axes"), eight, false},
                {QStringLiteral("3 axes (1, 2, 5)"), three, false},
                {QStringLiteral("8 axes, the first stop's answer lost"), eight, true}};
    for (const auto& row : rows) {
        const StopRun run = measureStop(row.axes, row.lose);
        const double limit = double(run.stopWire) * 10 / kBaud;
        QTextStream(stdout) << QStringLiteral("| %1 | %2 | %3 | %4 s | %5 s | %6 | %7 s | %8 |\n")
                                   .arg(row.what)
                                   .arg(run.stops)
                                   .arg(run.stopWire)
                                   .arg(run.toLastAck, 0, 'f', 3)
                                   .arg(limit, 0, 'f', 3)
                                   .arg(run.toLastAck / limit, 0, 'f', 2)
                                   .arg(run.whole, 0, 'f', 3)
                                   .arg(run.acknowledged ? QStringLiteral("yes")
                                                         : QStringLiteral("no"));
    }
}

}  // namespace

void benchMc1(bool stopOnly) {
    benchStop();
    benchMc1LiveStop();
    if (stopOnly) return;
    QTextStream(stdout) << "| operation | controller | wire B | requests | time | wire limit "
                           "| ratio |\n| --- | --- | ---: | ---: | ---: | ---: | ---: |\n";
    for (Mc1Variant variant : allMc1Variants()) {
        printRow(QStringLiteral("1000 variables (RDVAR)"), variant,
                 measure(variant, readVariables));
        if (isMc200(variant)) {
            const bool v2 = variant == Mc1Variant::Mc200V2;
            printRow(v2 ? QStringLiteral("32 KiB memory (RDMEM, 125 B)")
                        : QStringLiteral("32 KiB memory (RDMEM6, 6 B)"),
                     variant, measure(variant, [](Mc1Device& device) -> Status {
                         const Result<QByteArray> bytes = device.readMemory(0, kRange);
                         return bytes ? success() : Status(bytes.error());
                     }));
        } else {
            const bool block = variant == Mc1Variant::Mc100V2;
            const int bytes = block ? kRange : kSingleRange;
            printRow(block ? QStringLiteral("32 KiB RAM pages (RDBLOCK, 56 B)")
                           : QStringLiteral("1 KiB RAM pages (RDBYTE, 1 B)"),
                     variant, measure(variant, [bytes](Mc1Device& device) {
                         return readPages(device, bytes);
                     }));
        }
    }
}

}  // namespace cambench::bench
