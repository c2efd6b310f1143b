// Prints how close CamBench's bulk transfers come to the wire limit of the
// line (bytes on the wire x 10 bits / baud) against the throttled in-process
// simulator, clean and with damaged and lost replies, and how many results
// differ from what the simulator holds. Figures, not assertions: run it when
// asked (it takes minutes); docs/performance.md records a run.

#include "cambus_bench.h"
#include "compax3_bench.h"
#include "machine_bench.h"
#include "mc1_bench.h"
#include "protocol_bench.h"

#include "comm/camcon/ascii/ascii_camcon.h"
#include "comm/camcon/ascii/ascii_link.h"
#include "comm/device/protocol_registry.h"
#include "comm/sim/camcon/camcon_simulator.h"
#include "comm/sim/camcon/sim_camcon_endpoint.h"
#include "comm/sim/camcon/sim_device.h"
#include "comm/sim/camcon/sim_eeprom_format.h"
#include "comm/sim/sim_transport.h"

#include "app/registry/builtin_registry.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QLoggingCategory>
#include <QTextStream>

#include <algorithm>
#include <functional>
#include <optional>

using namespace cambench;
using namespace cambench::comm;

namespace {

QTextStream& out() {
    static QTextStream stream(stdout);
    return stream;
}

// One way of talking to the device: a framing at its usual baud rate.
struct Line {
    QString name;
    Framing framing;
    int baud;
};

// What the simulator does to the replies.
struct Faults {
    QString name;
    double corrupt = 0;  // damaged replies
    double drop = 0;     // lost replies (the request was executed)
};

const QList<Faults>& faultRows() {
    static const QList<Faults> rows{{QStringLiteral("clean"), 0, 0},
                                    {QStringLiteral("1 % damaged"), 0.01, 0},
                                    {QStringLiteral("1 % lost"), 0, 0.01},
                                    {QStringLiteral("1 % damaged + 1 % lost"), 0.01, 0.01}};
    return rows;
}

// A simulated line with the client on top, as the tools use it.
struct Rig {
    Rig(const Line& line, const Faults& faults, int fill, quint32 seed, QList<int> devices = {0}) {
        SimPortConfig config;
        config.devices = std::move(devices);
        config.framing = line.framing;
        config.baud = line.baud;
        config.fill = fill;
        config.faults.corruptProbability = faults.corrupt;
        config.faults.dropProbability = faults.drop;
        config.faults.seed = seed;
        firstDevice = config.devices.first();
        transport = std::make_unique<SimTransport>(camConSimulatedLine(config));
        if (const Status opened = transport->open(); !opened)
            qFatal("%s", qPrintable(opened.error().message));
        AsciiSettings settings;  // timeouts derived from the line, as by default
        settings.framing = line.framing;
        settings.device = config.devices.first();
        SerialSettings serial;
        serial.baud = line.baud;
        link = std::make_unique<AsciiLink>(*transport, settings, lineTimingFor(serial));
        client = std::make_unique<AsciiCamCon>(*link);
    }
    SimDevice& device() {
        return *dynamic_cast<SimCamConEndpoint&>(transport->line()).device(firstDevice);
    }
    // The EEPROM blocks the simulated device holds now.
    QList<QByteArray> eeprom() {
        return sim_eeprom::serialize(device().state(), device().profile());
    }

    int firstDevice = 0;
    std::unique_ptr<SimTransport> transport;
    std::unique_ptr<AsciiLink> link;
    std::unique_ptr<AsciiCamCon> client;
};

struct Run {
    double seconds = 0;
    AsciiLink::Stats stats;
    int wrong = 0;    // results that differ from what the simulator holds
    QString failure;  // the operation failed (honestly): its message
};

// Several runs of one row, with seeds 7, 8, ...: the median time (the
// machine is shared), the counters and wrong results summed.
struct Row {
    double seconds = 0;
    qint64 wireBytes = 0;  // of one run
    int runs = 0;
    int retries = 0;
    int silentAttempts = 0;
    int wrong = 0;
    QString failure;
};

int g_repeat = 1;

Row measureRow(const std::function<Run(quint32 seed)>& measure) {
    Row row;
    QList<double> times;
    for (int i = 0; i < g_repeat; ++i) {
        const Run run = measure(quint32(7 + i));
        times.append(run.seconds);
        row.wireBytes = run.stats.bytesSent + run.stats.bytesReceived;
        row.retries += run.stats.retries;
        row.silentAttempts += run.stats.silentAttempts;
        row.wrong += run.wrong;
        if (row.failure.isEmpty()) row.failure = run.failure;
        ++row.runs;
    }
    std::sort(times.begin(), times.end());
    row.seconds = times.at(times.size() / 2);
    return row;
}

Run timed(Rig& rig, const std::function<void(Run&)>& work) {
    Run run;
    QElapsedTimer timer;
    timer.start();
    work(run);
    run.seconds = timer.nsecsElapsed() / 1e9;
    run.stats = rig.link->stats();
    return run;
}

double wireSeconds(qint64 bytes, int baud) {
    return double(bytes) * 10.0 / baud;
}

void printHeader() {
    out() << QStringLiteral(
                 "median of %1 run(s), seeds 7..%2; retries and silent attempts per "
                 "run\n\n")
                 .arg(g_repeat)
                 .arg(6 + g_repeat);
    out() << "| operation | line | replies | time | x wire limit | x clean | retries | silent "
             "attempts | wrong results |\n"
             "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    out().flush();
}

// `clean`: the same operation without faults; its wire bytes are the limit.
void printRow(const QString& operation, const Line& line, const Faults& faults, const Row& row,
              const Row& clean) {
    const double limit = wireSeconds(clean.wireBytes, line.baud);
    out() << QStringLiteral("| %1 | %2 | %3 | %4 s | %5 | %6 | %7 | %8 | %9 |\n")
                 .arg(operation, line.name, faults.name)
                 .arg(row.seconds, 0, 'f', 2)
                 .arg(row.seconds / limit, 0, 'f', 3)
                 .arg(row.seconds / clean.seconds, 0, 'f', 3)
                 .arg(double(row.retries) / row.runs, 0, 'f', 1)
                 .arg(double(row.silentAttempts) / row.runs, 0, 'f', 1)
                 .arg(row.failure.isEmpty() ? QString::number(row.wrong)
                                            : QStringLiteral("failed: ") + row.failure);
    out().flush();
}

int differingBlocks(const QList<QByteArray>& device, const QList<EepromBlock>& image) {
    int wrong = int(qAbs(device.size() - image.size()));
    for (int i = 0; i < qMin(device.size(), image.size()); ++i)
        wrong += device.at(i) == image.at(i).data ? 0 : 1;
    return wrong;
}

// 8 cams on each of 32 outputs of 16 programs: more than 32 KiB of blocks.
constexpr int kEepromFill = 8;
constexpr int kProgramFill = 20;

void benchEeprom(const Line& line) {
    // The image to restore: a clean backup of the filled device.
    EepromImage image;
    {
        Rig source(line, faultRows().first(), kEepromFill, 7);
        Result<EepromImage> taken = source.client->backup();
        if (!taken) qFatal("%s", qPrintable(taken.error().message));
        image = std::move(taken).value();
    }
    std::optional<Row> cleanBackup;
    std::optional<Row> cleanRestore;
    for (const Faults& faults : faultRows()) {
        int blocks = 0;
        const Row backup = measureRow([&](quint32 seed) {
            Rig source(line, faults, kEepromFill, seed);
            const QList<QByteArray> held = source.eeprom();
            blocks = int(held.size());
            return timed(source, [&](Run& run) {
                const Result<EepromImage> taken = source.client->backup();
                if (!taken) {
                    run.failure = taken.error().message;
                    return;
                }
                run.wrong = differingBlocks(held, taken->blocks);
            });
        });
        if (!cleanBackup) cleanBackup = backup;
        printRow(QStringLiteral("EEPROM backup (%1 blocks)").arg(blocks), line, faults, backup,
                 *cleanBackup);

        // A fresh device with the demo state; the image of the filled one.
        const Row restore = measureRow([&](quint32 seed) {
            Rig target(line, faults, 0, seed);
            return timed(target, [&](Run& run) {
                if (const Status done = target.client->restore(image); !done) {
                    run.failure = done.error().message;
                    return;
                }
                run.wrong = differingBlocks(target.eeprom(), image.blocks);
            });
        });
        if (!cleanRestore) cleanRestore = restore;
        printRow(QStringLiteral("EEPROM restore (%1 blocks)").arg(image.blocks.size()), line,
                 faults, restore, *cleanRestore);
    }
}

void benchProgram(const Line& line) {
    std::optional<Row> clean;
    for (const Faults& faults : faultRows()) {
        int cams = 0;
        const Row read = measureRow([&](quint32 seed) {
            Rig rig(line, faults, kProgramFill, seed);
            const SimCamStore held = rig.device().state().cams;
            return timed(rig, [&](Run& run) {
                const Result<CamProgram> program = rig.client->readProgram(0, 32);
                if (!program) {
                    run.failure = program.error().message;
                    return;
                }
                cams = 0;
                for (int output = 1; output <= 32; ++output) {
                    const QList<Cam> expected = held.track(0, output - 1);
                    const QList<Cam> got = program->tracks.value(output).cams;
                    run.wrong += got == expected ? 0 : 1;
                    cams += int(got.size());
                }
            });
        });
        if (!clean) clean = read;
        printRow(QStringLiteral("read program 0 (32 tracks, %1 cams)").arg(cams), line, faults,
                 read, *clean);
    }
}

void benchScan(const Line& line) {
    const QList<int> devices{0, 31, 63};
    QList<int> found;
    qint64 requests = 0;
    const Row scan = measureRow([&](quint32 seed) {
        Rig rig(line, faultRows().first(), 0, seed, devices);
        return timed(rig, [&](Run& run) {
            const Result<QList<int>> result = rig.client->scanBus(0, 63);
            requests = rig.link->stats().requests;
            if (!result) {
                run.failure = result.error().message;
                return;
            }
            found = *result;
            run.wrong = found == devices ? 0 : 1;
        });
    });
    // The least a scan can put on the wire: one ?UNIT per number, one
    // :UNIT per device.
    const MultiuserAddress address{63, 0, 0};
    const qint64 floorBytes =
        64 * encodeFrame(Frame{kQuery, "UNIT", address, true}).size() +
        devices.size() * encodeFrame(Frame{kReply, "UNIT", address, true}).size();
    out() << QStringLiteral(
                 "\nscan of 64 numbers, devices at 0, 31, 63, %1: %2 s; on the wire "
                 "%3 s (%4 requests, x %5); one look per number would need %6 s "
                 "(x %7); wrong results %8\n")
                 .arg(line.name)
                 .arg(scan.seconds, 0, 'f', 2)
                 .arg(wireSeconds(scan.wireBytes, line.baud), 0, 'f', 3)
                 .arg(requests)
                 .arg(scan.seconds / wireSeconds(scan.wireBytes, line.baud), 0, 'f', 1)
                 .arg(wireSeconds(floorBytes, line.baud), 0, 'f', 3)
                 .arg(scan.seconds / wireSeconds(floorBytes, line.baud), 0, 'f', 1)
                 .arg(scan.failure.isEmpty() ? QString::number(scan.wrong) : scan.failure);
    out().flush();
}

}  // namespace

int main(int argc, char** argv) {
    cambench::registerBuiltins();
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Measures bulk transfers against the throttled simulator, clean and with 1 % damaged and "
        "lost replies (about 12 minutes per --repeat; --quick about 3)."));
    parser.addHelpOption();
    QCommandLineOption quick(QStringLiteral("quick"),
                             QStringLiteral("Only Multiuser at 38400 baud (skips Standard 9600)."));
    parser.addOption(quick);
    QCommandLineOption protocols(
        QStringLiteral("protocols"),
        QStringLiteral("Only a program of 32 tracks x 20 cams read and written over CamCon "
                       "ASCII and the table interface (3964R n96, e38) at the same baud rates."));
    parser.addOption(protocols);
    QCommandLineOption mc1(QStringLiteral("mc1"),
                           QStringLiteral("Only MC100/MC200: 1,000 variables and a 32 KiB range "
                                          "of each variant at 9600 baud (about 4 minutes)."));
    parser.addOption(mc1);
    QCommandLineOption mc1Stop(QStringLiteral("mc1-stop"),
                               QStringLiteral("Only the MC200's STOP of every axis at 9600 baud "
                                              "(a few seconds)."));
    parser.addOption(mc1Stop);
    QCommandLineOption compax3(
        QStringLiteral("compax3"),
        QStringLiteral("Only Compax3: a 500-object parameter set at 115200 and 9600 baud."));
    parser.addOption(compax3);
    QCommandLineOption cambus(
        QStringLiteral("cambus"),
        QStringLiteral("Only Cam-BUS: an EEPROM backup and a program read of one CamCon at 38400 "
                       "baud while two displays poll."));
    parser.addOption(cambus);
    QCommandLineOption cambusAnswers(
        QStringLiteral("cambus-answers"),
        QStringLiteral("Only the PC's answer times on a Cam-BUS: cambench-cli backup, restore and "
                       "verify against cambench-sim at 38400 baud and T = 10 ms (a display "
                       "polling), as the simulated users saw them."));
    parser.addOption(cambusAnswers);
    QCommandLineOption machine(
        QStringLiteral("machine"),
        QStringLiteral("Only a machine: `cambench-cli machine backup` of a CamCon, an MC200 and "
                       "a Compax3 on three ptys at 38400 baud, each alone and all at once."));
    parser.addOption(machine);
    QCommandLineOption repeat(QStringLiteral("repeat"),
                              QStringLiteral("Runs per row, with seeds 7, 8, ...; the median time "
                                             "is printed (default 1)."),
                              QStringLiteral("n"), QStringLiteral("1"));
    parser.addOption(repeat);
    parser.process(app);
    g_repeat = qBound(1, parser.value(repeat).toInt(), 20);
    // The figures are the output; the link's warnings about each retry are not.
    QLoggingCategory::setFilterRules(QStringLiteral("cambench.*.warning=false"));

    const Line standard{QStringLiteral("Standard 9600"), Framing::Standard, 9600};
    const Line multiuser{QStringLiteral("Multiuser 38400"), Framing::Multiuser, 38400};
    const QList<Line> lines =
        parser.isSet(quick) ? QList<Line>{multiuser} : QList<Line>{standard, multiuser};
    if (parser.isSet(cambusAnswers)) {
        bench::benchCamBusAnswers();
        return 0;
    }
    if (parser.isSet(cambus)) {
        bench::benchCamBus();
        return 0;
    }
    if (parser.isSet(machine)) {
        bench::benchMachine(38400, g_repeat);
        return 0;
    }
    if (parser.isSet(compax3)) {
        bench::benchCompax3();
        return 0;
    }
    if (parser.isSet(mc1) || parser.isSet(mc1Stop)) {
        bench::benchMc1(parser.isSet(mc1Stop));
        return 0;
    }
    if (parser.isSet(protocols)) {
        bench::benchProtocols(parser.isSet(quick) ? QList<int>{38400} : QList<int>{9600, 38400});
        return 0;
    }
    printHeader();
    for (const Line& line : lines) {
        benchEeprom(line);
        benchProgram(line);
    }
    benchScan(multiuser);
    return 0;
}
