// Prints how close CamBench's transfers come to the wire limit of the line
// (bytes on the wire x 10 bits / baud) against the throttled in-process
// simulator, and what retries cost under 1 % corrupted replies. Figures,
// not assertions: docs/performance.md records a run.

#include "protocol_bench.h"

#include "comm/camcon/ascii/ascii_link.h"
#include "comm/camcon/ascii/ascii_camcon.h"
#include "app/registry/builtin_registry.h"
#include "comm/device/protocol_registry.h"
#include "comm/transport/transport_registry.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QLoggingCategory>
#include <QTextStream>

#include <cstdio>
#include <functional>

using namespace cambench;
using namespace cambench::comm;

namespace {

QTextStream& out() {
    static QTextStream stream(stdout);
    return stream;
}

struct Measurement {
    double seconds = 0;
    AsciiLink::Stats stats;
};

// Opens a fresh simulated device described by `simOptions` at `baud` and
// runs `work` on it; the line's counters give the bytes that crossed the wire.
Measurement measure(const QString& simOptions, int baud,
                    const std::function<void(AsciiCamCon&, AsciiLink&)>& work) {
    ConnectionSettings connection;
    connection.port = QStringLiteral("sim:baud=%1;%2").arg(baud).arg(simOptions);
    connection.serial.baud = baud;
    auto transport = makeTransport(connection);
    if (!transport) {
        std::fprintf(stderr, "cambench-bench: %s\n", qPrintable(transport.error().message));
        std::exit(3);
    }
    std::unique_ptr<Transport> pipe = std::move(transport).value();
    if (Status opened = pipe->open(); !opened) {
        std::fprintf(stderr, "cambench-bench: %s\n", qPrintable(opened.error().message));
        std::exit(3);
    }
    AsciiSettings settings;  // the per-attempt timeout derives from the line
    if (simOptions.contains(QStringLiteral("framing=multiuser"))) settings.framing = Framing::Multiuser;
    AsciiLink link(*pipe, settings, lineTimingFor(connection.serial));
    AsciiCamCon client(link);
    QElapsedTimer timer;
    timer.start();
    work(client, link);
    return {timer.nsecsElapsed() / 1e9, link.stats()};
}

double wireLimitSeconds(const AsciiLink::Stats& stats, int baud) {
    return double(stats.bytesSent + stats.bytesReceived) * 10.0 / baud;
}

void printRow(const QString& what, int baud, const Measurement& m, qint64 payloadBytes) {
    const double limit = wireLimitSeconds(m.stats, baud);
    out() << QStringLiteral("%1 | %2 | %3 | %4 | %5 | %6 s | %7 s | %8 | %9\n")
                 .arg(what, -34)
                 .arg(baud, 6)
                 .arg(payloadBytes, 7)
                 .arg(m.stats.bytesSent + m.stats.bytesReceived, 7)
                 .arg(m.stats.requests, 6)
                 .arg(m.seconds, 7, 'f', 2)
                 .arg(limit, 7, 'f', 2)
                 .arg(m.seconds / limit, 5, 'f', 2)
                 .arg(m.stats.retries, 4);
    out().flush();
}

void fail(const Error& error) {
    std::fprintf(stderr, "cambench-bench: %s\n", qPrintable(error.message));
    std::exit(error.kind == ErrorKind::DeviceError ? 1 : 3);
}

QString faultText(const QString& faults) {
    QString text;
    if (faults.contains(QStringLiteral("corrupt"))) text += QStringLiteral(", 1 % corrupt");
    if (faults.contains(QStringLiteral("multiuser"))) text += QStringLiteral(", Multiuser");
    return text;
}

qint64 imageBytes(const EepromImage& image) {
    qint64 total = 0;
    for (const EepromBlock& block : image.blocks) total += block.data.size();
    return total;
}

void benchEeprom(int baud, const QString& faults) {
    // 8 cams on each of 32 outputs of 16 programs: more than 32 KiB of blocks.
    const QString options = QStringLiteral("fill=8") + faults;
    EepromImage image;
    const Measurement backup = measure(options, baud, [&](AsciiCamCon& client, AsciiLink&) {
        auto result = client.backup();
        if (!result) fail(result.error());
        image = result.value();
    });
    printRow(QStringLiteral("EEPROM backup (%1 blocks)%2").arg(image.blocks.size())
                 .arg(faultText(faults)),
             baud, backup, imageBytes(image));
    const Measurement restore = measure(options, baud, [&](AsciiCamCon& client, AsciiLink&) {
        if (Status done = client.restore(image); !done) fail(done.error());
    });
    printRow(QStringLiteral("EEPROM restore (%1 blocks)%2").arg(image.blocks.size())
                 .arg(faultText(faults)),
             baud, restore, imageBytes(image));
}

void benchProgram(int baud, const QString& faults) {
    int cams = 0;
    const Measurement read = measure(QStringLiteral("fill=20") + faults, baud,
                                     [&](AsciiCamCon& client, AsciiLink&) {
                                         auto program = client.readProgram(0, 32);
                                         if (!program) fail(program.error());
                                         for (const Track& track : program->tracks)
                                             cams += int(track.cams.size());
                                     });
    printRow(QStringLiteral("read program 0 (32 tracks, %1 cams)%2").arg(cams)
                 .arg(faultText(faults)),
             baud, read, qint64(cams) * 8);
}

}  // namespace

int main(int argc, char** argv) {
    cambench::registerBuiltins();
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Measures transfers against the throttled simulator."));
    parser.addHelpOption();
    QCommandLineOption quick(QStringLiteral("quick"),
                             QStringLiteral("Only 38400 baud (skips the slow 9600 runs)."));
    parser.addOption(quick);
    QCommandLineOption protocols(
        QStringLiteral("protocols"),
        QStringLiteral("Only a program of 32 tracks x 20 cams read and written over CamCon "
                       "ASCII and the table interface (3964R n96, e38) at the same baud rates."));
    parser.addOption(protocols);
    parser.process(app);
    // The figures are the output; the link's warnings about each retry are not.
    QLoggingCategory::setFilterRules(QStringLiteral("cambench.*.warning=false"));

    const QList<int> bauds = parser.isSet(quick) ? QList<int>{38400} : QList<int>{9600, 38400};
    if (parser.isSet(protocols)) {
        bench::benchProtocols(bauds);
        return 0;
    }
    out() << "operation                          |   baud | payload |    wire | "
             "reqs |    time   | wire limit | ratio | retries\n";
    for (int baud : bauds) {
        benchEeprom(baud, {});
        benchProgram(baud, {});
    }
    // What retries cost: the same transfers with 1 % of replies corrupted.
    const QString corrupt = QStringLiteral(";corrupt=0.01;seed=7");
    benchProgram(38400, corrupt);
    benchEeprom(38400, corrupt);
    // Multiuser: block numbers make every retry safe, so the link retries.
    benchEeprom(38400, corrupt + QStringLiteral(";framing=multiuser"));
    return 0;
}
