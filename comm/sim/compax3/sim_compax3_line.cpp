#include "sim_compax3_line.h"
#include "comm/engine/cr_line_backend.h"

#include "comm/compax3/compax3_syntax.h"
#include "comm/sim/sim_log.h"

namespace cambench::comm {

QString SimCompax3Line::protocolName() const {
    return m_address < 0 ? QStringLiteral("Compax3 RS232")
                         : QStringLiteral("Compax3 RS485 address %1").arg(m_address);
}

void SimCompax3Line::driveShaft(std::shared_ptr<SimShaft> shaft) {
    m_shaft = std::make_unique<SimShaftDriver>(std::move(shaft));
    m_shaft->publish(m_drive.motion());
}

QList<SimOutput> SimCompax3Line::receive(QByteArrayView bytes, qint64 nowMs) {
    QList<SimOutput> out;
    m_pending.append(bytes.toByteArray());
    while (std::optional<QByteArray> line = takeCrLine(m_pending)) {
        QByteArray command = line->trimmed();
        if (m_address >= 0) {
            // The address: the decimal digits in front.
            int digits = 0;
            while (digits < command.size() && digits < 2 && std::isdigit(uchar(command.at(digits))))
                ++digits;
            if (digits == 0 || command.left(digits).toInt() != m_address) continue;
            command.remove(0, digits);
        }
        if (m_faults.settings().dead || m_faults.ignoresRequest()) continue;
        // --verbose: every request, so that a test counts what reached it.
        qCDebug(commSimLog).noquote() << "<-" << QString::fromLatin1(command);
        QByteArray reply = m_drive.answer(command, nowMs);
        if (m_shaft) m_shaft->publish(m_drive.motion());
        if (m_address >= 0) reply.prepend(kCompax3Rs485Mark);
        if (std::optional<SimOutput> sent =
                m_faults.apply(SimOutput{reply + kCompax3End, 1 + m_delayMs}, command))
            out << *sent;
    }
    return out;
}

}  // namespace cambench::comm
