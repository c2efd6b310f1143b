#include "mc1_bench.h"

#include "bench_run.h"

#include "comm/mc1/mc1_controller.h"
#include "comm/sim/mc1/mc1_simulator.h"
#include "comm/sim/sim_transport.h"

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
    Mc1Controller device(transport, Mc1Settings{variant, 0, 2}, line);
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

}  // namespace

void benchMc1() {
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
