#include "sim_mc1_line.h"

#include "comm/mc1/mc1_telegram.h"
#include "comm/sim/sim_log.h"

#include <QStringList>

namespace cambench::comm {

namespace {
constexpr int kCharacterTimeoutMs = 100;
}  // namespace

void SimMc1Line::setSync(int periodMs) {
    m_syncPeriod = periodMs;
    m_nextSync = -1;
}

qint64 SimMc1Line::nextTimerMs() const {
    qint64 next = m_pending.isEmpty() ? -1 : m_deadline;
    if (m_syncPeriod > 0)
        next = next < 0 ? std::max<qint64>(0, m_nextSync) : std::min(next, m_nextSync);
    return next;
}

Status SimMc1Line::driveShaft(std::shared_ptr<SimShaft> shaft, int axis) {
    if (!m_controller.axes().contains(axis)) {
        QStringList axes;
        for (int present : m_controller.axes()) axes << QString::number(present);
        return Error::usage(QStringLiteral("the simulated MC-1 has no axis %1 to drive the shaft "
                                           "(its axes: %2)")
                                .arg(axis)
                                .arg(axes.join(QLatin1String(", "))));
    }
    m_shaftAxis = axis;
    m_shaft = std::make_unique<SimShaftDriver>(std::move(shaft));
    m_shaft->publish(m_controller.axisMotion(axis, 0));
    return success();
}

QList<SimOutput> SimMc1Line::receive(QByteArrayView bytes, qint64 nowMs) {
    QList<SimOutput> out;
    if (m_syncPeriod > 0 && m_pending.isEmpty()) {
        // A telegram starts: only inside the window after a 0xFF, once.
        const qint64 window = m_syncPeriod <= 5 ? 2 : 4;
        if (!m_windowOpen || nowMs - m_lastSync > window) {
            ++m_outsideWindow;
            return out;
        }
        m_windowOpen = false;
    }
    m_pending.append(bytes.toByteArray());
    while (!m_pending.isEmpty()) {
        const int length = m_controller.requestLength(m_pending);
        if (length < 0) {
            m_pending.clear();
            out << SimOutput{QByteArray(1, char(kMc1Nak)), 0};
            break;
        }
        if (length == 0 || m_pending.size() < length) break;
        const QByteArray telegram = m_pending.left(length);
        m_pending.remove(0, length);
        if (m_faults.settings().dead || m_faults.ignoresRequest()) continue;
        // --verbose: every telegram, so that a test counts what reached it.
        qCDebug(commSimLog).noquote() << "<-" << QString::fromLatin1(telegram.toHex(' '));
        const QByteArray answer = m_controller.handle(telegram, nowMs);
        if (m_shaft) m_shaft->publish(m_controller.axisMotion(m_shaftAxis, nowMs));
        if (answer.isEmpty()) continue;
        if (std::optional<SimOutput> sent = m_faults.apply(SimOutput{answer, 0}, telegram))
            out << *sent;
    }
    m_deadline = nowMs + kCharacterTimeoutMs;
    return out;
}

QList<SimOutput> SimMc1Line::poll(qint64 nowMs) {
    QList<SimOutput> out;
    if (m_syncPeriod > 0 && nowMs >= m_nextSync) {
        // A late poll sends one 0xFF, not the ones it missed; its window
        // counts from when it leaves (provisional: the notes count the
        // window to the telegram's first byte, from the 0xFF).
        out << SimOutput{QByteArray(1, char(kMc1Sync)), 0};
        m_lastSync = nowMs;
        m_nextSync = nowMs + m_syncPeriod;
        m_windowOpen = true;
    }
    if (!m_pending.isEmpty() && nowMs >= m_deadline) {
        m_pending.clear();
        out << SimOutput{QByteArray(1, char(kMc1Nak)), 0};
    }
    return out;
}

QString SimMc1Line::protocolName() const {
    return QStringLiteral("MC-1 (%1)").arg(mc1VariantName(m_controller.variant()));
}

}  // namespace cambench::comm
