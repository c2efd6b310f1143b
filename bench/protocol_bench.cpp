#include "protocol_bench.h"

#include "comm/camcon/camcon_device.h"
#include "comm/device/protocol_registry.h"
#include "comm/transport/transport_registry.h"

#include <QElapsedTimer>
#include <QTextStream>

#include <cstdio>
#include <memory>

namespace cambench::bench {

namespace {

using namespace cambench::comm;

constexpr int kTracks = 32;
constexpr int kCamsPerTrack = 20;

struct Run {
    double seconds = 0;
    RequestEngine::Stats stats;
};

[[noreturn]] void fail(const Error& error) {
    std::fprintf(stderr, "cambench-bench: %s\n", qPrintable(error.message));
    std::exit(error.kind == ErrorKind::DeviceError ? 1 : 3);
}

// A fresh simulated device with 20 cams on every track, spoken to in
// `protocol` at `baud`; `work` runs on it and is timed.
Run measure(const QString& protocol, int baud, const std::function<void(CamConDevice&)>& work,
            int* bitsPerByte) {
    const ProtocolInfo* info = ProtocolRegistry::instance().find(protocol);
    ConnectionSettings connection;
    connection.serial = info->defaultSerial;
    connection.serial.baud = baud;
    connection.protocol = protocol;
    connection.port = QStringLiteral("sim:baud=%1;fill=%2").arg(baud).arg(kCamsPerTrack);
    Result<std::unique_ptr<Transport>> transport = makeTransport(connection);
    if (!transport) fail(transport.error());
    if (Status opened = (*transport)->open(); !opened) fail(opened.error());
    const LineTiming line = lineTimingFor(connection.serial);
    *bitsPerByte = line.bitsPerByte;
    Result<std::unique_ptr<DeviceConnection>> connected =
        info->connect(**transport, *info->makeSettings(), line);
    if (!connected) fail(connected.error());
    auto* device = dynamic_cast<CamConDevice*>(connected->get());
    QElapsedTimer timer;
    timer.start();
    work(*device);
    return {timer.nsecsElapsed() / 1e9, device->engine().stats()};
}

void printRow(const QString& what, const QString& protocol, int baud, int bitsPerByte,
              const Run& run) {
    const qint64 wire = run.stats.bytesSent + run.stats.bytesReceived;
    const double limit = double(wire) * bitsPerByte / baud;
    QTextStream(stdout) << QStringLiteral("| %1 | %2 | %3 | %4 | %5 | %6 s | %7 s | %8 |\n")
                               .arg(what, protocol)
                               .arg(baud)
                               .arg(wire)
                               .arg(run.stats.requests)
                               .arg(run.seconds, 0, 'f', 2)
                               .arg(limit, 0, 'f', 2)
                               .arg(run.seconds / limit, 0, 'f', 2);
}

}  // namespace

void benchProtocols(const QList<int>& bauds) {
    QTextStream(stdout) << "| operation | protocol | baud | wire B | requests | time | wire limit "
                           "| ratio |\n| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    // The program written: 20 cams per track, other points than the ones filled.
    QList<Track> tracks;
    for (int output = 1; output <= kTracks; ++output) {
        Track track{output, {}};
        for (int i = 0; i < kCamsPerTrack; ++i)
            track.cams.append({qint32(18 * i + 2), qint32(18 * i + 11)});
        tracks.append(track);
    }
    for (int baud : bauds) {
        for (const char* protocol : {"standard", "3964r-n96", "3964r-e38"}) {
            int bits = 10;
            int cams = 0;
            const Run read = measure(
                protocol, baud,
                [&](CamConDevice& device) {
                    Result<CamProgram> program = device.readProgram(0, kTracks);
                    if (!program) fail(program.error());
                    for (const Track& track : program->tracks) cams += int(track.cams.size());
                },
                &bits);
            printRow(QStringLiteral("read program 0 (%1 cams)").arg(cams), protocol, baud, bits,
                     read);
            const Run write = measure(
                protocol, baud,
                [&](CamConDevice& device) {
                    for (const Track& track : tracks)
                        if (Status done = device.writeTrack(1, track); !done) fail(done.error());
                },
                &bits);
            printRow(QStringLiteral("write program 1 (%1 cams)").arg(kTracks * kCamsPerTrack),
                     protocol, baud, bits, write);
        }
    }
}

}  // namespace cambench::bench
