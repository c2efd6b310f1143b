#include "sim_transport.h"

#include <QThread>

#include <algorithm>
#include <optional>

namespace cambench::comm {

namespace {
// Longest sleep between looks at the clock: short enough that a reply is
// seen within a byte time at 9600 baud.
constexpr qint64 kSliceUs = 1000;
}  // namespace

SimTransport::SimTransport(SimulatedLine line)
    : SimTransport(std::move(line.endpoint), line.pacer, std::move(line.description)) {}

SimTransport::SimTransport(std::unique_ptr<SimEndpoint> line, const SimPacer& pacer,
                           QString description)
    : m_description(std::move(description)), m_line(std::move(line)), m_pacer(pacer) {
    m_clock.start();
}

Status SimTransport::open() {
    m_open = true;
    return success();
}

void SimTransport::close() {
    m_open = false;
    m_pending.clear();
}

Status SimTransport::write(const QByteArray& bytes) {
    if (!m_open) return Error::communication(QStringLiteral("%1 is not open.").arg(description()));
    const qint64 sentUs = nowUs();
    m_pending.append(
        m_pacer.schedule(sentUs, int(bytes.size()), m_line->receive(bytes, sentUs / 1000)));
    return success();
}

void SimTransport::pollLine() {
    const qint64 timer = m_line->nextTimerMs();
    const qint64 now = nowUs();
    if (timer < 0 || now / 1000 < timer) return;
    m_pending.append(m_pacer.schedule(now, 0, m_line->poll(now / 1000)));
}

Result<QByteArray> SimTransport::read(int timeoutMs) {
    if (!m_open) return Error::communication(QStringLiteral("%1 is not open.").arg(description()));
    const qint64 deadlineUs = nowUs() + qint64(std::max(timeoutMs, 0)) * 1000;
    for (;;) {
        pollLine();
        const qint64 now = nowUs();
        QByteArray bytes = m_pending.takeDue(now);
        if (!bytes.isEmpty() || now >= deadlineUs) return bytes;
        qint64 wakeUs = deadlineUs;
        if (const auto due = m_pending.nextDueUs()) wakeUs = std::min(wakeUs, *due);
        if (const qint64 timer = m_line->nextTimerMs(); timer >= 0)
            wakeUs = std::min(wakeUs, timer * 1000);
        QThread::usleep(quint64(std::clamp<qint64>(wakeUs - now, 1, kSliceUs)));
    }
}

void SimTransport::discardInput() {
    m_pending.takeDue(nowUs());
}

QString SimTransport::description() const {
    return m_description;
}

namespace {

// The line of `port` as the PC speaking `protocol` meets it; without a
// protocol, as the port names it: the first family whose simulator takes
// the port's keys ("sim" is the first family's default device).
Result<SimulatedLine> simulatedLine(const QString& port, const SerialSettings& serial,
                                    const QString& protocol) {
    if (!protocol.isEmpty()) {
        const SimulatorInfo* simulator = SimulatorRegistry::instance().forProtocol(protocol);
        if (!simulator)
            return Error::usage(QStringLiteral("no simulator is built into this CamBench"));
        return simulator->fromPort(port, serial, protocol);
    }
    std::optional<Error> first;
    for (const SimulatorInfo* simulator : SimulatorRegistry::instance().all()) {
        Result<SimulatedLine> line = simulator->fromPort(port, serial, protocol);
        if (line) return line;
        if (!first) first = line.error();
    }
    if (first) return *first;
    return Error::usage(QStringLiteral("no simulator is built into this CamBench"));
}

}  // namespace

Result<std::unique_ptr<Transport>> makeSimTransport(const QString& port,
                                                    const SerialSettings& serial,
                                                    const QString& protocol) {
    // The shaft keys are the host's; the family reads the rest.
    const Result<SimPortWithShaft> split = takeSimShaftKeys(port);
    if (!split) return split.error();
    Result<SimulatedLine> line = simulatedLine(split->port, serial, protocol);
    if (!line) return line.error();
    if (split->seat) {
        const QString who = QStringLiteral("Simulator port \"%1\"").arg(port);
        if (const Status seated = seatOnShaft(line->shaft, *split->seat, who); !seated)
            return seated.error();
    }
    return std::unique_ptr<Transport>(std::make_unique<SimTransport>(std::move(line).value()));
}

bool isSimPort(const QString& port) {
    static const QString kPrefix = QStringLiteral("sim");
    return port == kPrefix || port.startsWith(kPrefix + QLatin1Char(':'));
}

QString simPortProtocol(const QString& port) {
    const Result<SimPortWithShaft> split = takeSimShaftKeys(port);
    if (!split) return {};
    for (const SimulatorInfo* simulator : SimulatorRegistry::instance().all()) {
        if (!simulator->namedProtocol) continue;
        const QString named = simulator->namedProtocol(split->port);
        if (!named.isEmpty()) return named;
    }
    return {};
}

void registerSimTransport(TransportRegistry& registry) {
    registry.add({QStringLiteral("sim"), isSimPort,
                  [](const ConnectionSettings& connection) {
                      return makeSimTransport(connection.port, connection.serial,
                                              connection.protocol);
                  },
                  simPortProtocol});
}

}  // namespace cambench::comm
