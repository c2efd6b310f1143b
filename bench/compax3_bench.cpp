#include "compax3_bench.h"

#include "bench_run.h"

#include "comm/compax3/compax3_drive.h"
#include "comm/compax3/usecases/compax3_parameters.h"
#include "comm/sim/compax3/sim_compax3_line.h"
#include "comm/sim/sim_transport.h"

#include <QElapsedTimer>
#include <QTextStream>

#include <cstdio>

namespace cambench::bench {

namespace {

using namespace cambench::comm;

constexpr int kObjects = 500;

// The shipped dictionary has 192 parameters: the 500 objects go through
// them in turn (each read costs the same on the wire).
QList<Compax3ObjectId> objects() {
    const QList<Compax3ObjectId> parameters = Compax3Dictionary::builtin().parameters();
    QList<Compax3ObjectId> ids;
    for (int i = 0; i < kObjects; ++i) ids << parameters.at(i % parameters.size());
    return ids;
}

Run measure(int baud, const std::function<Status(Compax3Device&)>& work) {
    SimTransport transport(std::make_unique<SimCompax3Line>(-1, SimCompax3Drive()),
                           SimPacer(baud, true, 10), QStringLiteral("simulated Compax3"));
    openOrExit(transport);
    LineTiming line;
    line.baud = baud;
    Compax3Drive device(transport, QStringLiteral("compax3"), -1, 0, line);
    return timeWork(device.engine(), [&] { return work(device); });
}

void printRow(const QString& what, int baud, const Run& run) {
    const double limit = double(run.wire) * 10 / baud;
    QTextStream(stdout) << QStringLiteral("| %1 | %2 | %3 | %4 | %5 s | %6 s | %7 |\n")
                               .arg(what)
                               .arg(baud)
                               .arg(run.wire)
                               .arg(run.requests)
                               .arg(run.seconds, 0, 'f', 2)
                               .arg(limit, 0, 'f', 2)
                               .arg(run.seconds / limit, 0, 'f', 2);
}

}  // namespace

void benchCompax3() {
    QTextStream(stdout) << "| operation | baud | wire B | requests | time | wire limit | ratio |\n"
                           "| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    const QList<Compax3ObjectId> ids = objects();
    for (int baud : {115200, 9600}) {
        printRow(QStringLiteral("500 objects, one read each"), baud,
                 measure(baud, [&ids](Compax3Device& device) -> Status {
                     for (const Compax3ObjectId& id : ids)
                         if (const Result<QString> value = device.readObject(id, false); !value)
                             return value.error();
                     return success();
                 }));
        printRow(QStringLiteral("500-object backup (read until two agree)"), baud,
                 measure(baud, [&ids](Compax3Device& device) -> Status {
                     const Result<usecases::Compax3Backup> backup =
                         usecases::takeCompax3Parameters(device, ids, Compax3Dictionary::builtin());
                     return backup ? success() : Status(backup.error());
                 }));
    }
}

}  // namespace cambench::bench
