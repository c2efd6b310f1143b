#include "sim_table_line.h"

#include "comm/camcon/table/frame_3964r.h"
#include "comm/camcon/table/table_map.h"
#include "comm/sim/camcon/sim_device.h"
#include "comm/sim/sim_log.h"

namespace cambench::comm {

using table::kDle;
using table::kNak;
using table::kStx;

namespace {

// Area 205 word 11 (serial mode): 4 = 3964R n96, 5 = 3964R e38.
qint32 serialMode(table::Rk512Variant variant) {
    return variant == table::Rk512Variant::E38 ? 5 : 4;
}

}  // namespace

SimTableLine::SimTableLine(table::Rk512Variant variant, std::unique_ptr<SimDevice> device)
    : m_device(std::move(device)),
      m_table(*m_device, variant),
      m_link(table::Link3964R::Priority::Low) {
    m_device->tableState().words.insert(
        {table::kConfigArea, table::tableWord(u"config.serial_mode")}, serialMode(variant));
    setFaults({});
}

SimTableLine::~SimTableLine() = default;

void SimTableLine::setFaults(const SimFaultSettings& faults) {
    m_faults = faults;
    m_random.seed(faults.seed);
}

SimDevice* SimTableLine::device(int number) const {
    Q_UNUSED(number);  // point to point: the one device whatever its number
    return m_device.get();
}

QString SimTableLine::protocolName() const {
    return QLatin1String(table::rk512VariantInfo(m_table.variant()).name);
}

bool SimTableLine::chance(double probability) {
    // Always draw, so that one setting does not shift the others' sequence.
    const double draw = m_random.generateDouble();
    return draw < probability;
}

QList<SimOutput> SimTableLine::receive(QByteArrayView bytes, qint64 nowMs) {
    if (m_faults.dead) return {};
    return handle(m_link.feed(bytes, nowMs), nowMs);
}

QList<SimOutput> SimTableLine::poll(qint64 nowMs) {
    if (m_faults.dead) return {};
    return handle(m_link.poll(nowMs), nowMs);
}

QList<SimOutput> SimTableLine::handle(table::Actions&& actions, qint64 nowMs) {
    for (const QString& line : std::as_const(actions.log)) qCDebug(commSimLog) << "3964R:" << line;
    if (actions.sendFailed) qCDebug(commSimLog) << "reply given up:" << *actions.sendFailed;
    QByteArray write = std::move(actions.write);
    if (!actions.received.isEmpty() && m_link.sending() && write.endsWith(kStx)) {
        // The link restarted the unacknowledged reply after the new telegram:
        // the new telegram supersedes it.
        write.chop(1);
        m_link.reset();
        ++m_counters.supersededReplies;
    }
    QList<QByteArray> telegrams = std::move(actions.received);
    if (!telegrams.isEmpty() && write.startsWith(kDle)) {
        // The acknowledgement of the PC's block.
        if (chance(m_faults.nakProbability)) {
            write[0] = kNak;  // "bad block": not executed
            telegrams.clear();
            ++m_counters.naks;
        } else if (chance(m_faults.lostDleProbability)) {
            write.remove(0, 1);  // taken and executed, but the PC never hears it
            ++m_counters.lostDles;
        }
    } else if (write == QByteArray(1, kDle) && telegrams.isEmpty() && !m_link.sending()) {
        // The answer to the PC's STX.
        if (chance(m_faults.lostDleProbability)) {
            write.clear();
            ++m_counters.lostDles;
        } else if (chance(m_faults.collisionProbability)) {
            write.prepend(kStx);  // its own start crossed the PC's; it yields
            ++m_counters.collisions;
        }
    } else if (write.size() >= 3 && write.at(write.size() - 3) == kDle &&
               write.at(write.size() - 2) == table::kEtx && m_link.sending()) {
        // The device's reply block.
        if (chance(m_faults.corruptProbability)) {
            write.back() = char(write.back() ^ 0x5A);
            ++m_counters.corruptBccs;
        }
    }
    QList<SimOutput> outputs;
    if (!write.isEmpty()) outputs.append({write, 0});
    for (const QByteArray& telegram : std::as_const(telegrams)) {
        ++m_counters.telegrams;
        const std::optional<QByteArray> reply = m_table.execute(telegram);
        if (!reply) continue;
        if (chance(m_faults.dropProbability)) {
            ++m_counters.droppedReplies;
            continue;
        }
        const table::Actions sent = m_link.send(*reply, nowMs);
        if (sent.sendFailed) {
            qCWarning(commSimLog) << "reply not sent:" << *sent.sendFailed;
            continue;
        }
        // The device works on the request before its STX goes out.
        const int delay = m_device->profile().processingDelayMs + m_faults.extraDelayMs;
        if (!sent.write.isEmpty()) outputs.append({sent.write, delay});
    }
    return outputs;
}

}  // namespace cambench::comm
