#include "sim_mc1_ascii_line.h"
#include "comm/engine/cr_line_backend.h"

#include "comm/mc1/mc1_ascii.h"

namespace cambench::comm {

QList<SimOutput> SimMc1AsciiLine::receive(QByteArrayView bytes, qint64) {
    QList<SimOutput> out;
    m_pending.append(bytes.toByteArray());
    while (const std::optional<QByteArray> line = takeCrLine(m_pending)) {
        if (m_faults.settings().dead || m_faults.ignoresRequest()) continue;
        if (std::optional<SimOutput> sent =
                m_faults.apply(SimOutput{answer(*line) + '\r', 0}, *line))
            out << *sent;
    }
    return out;
}

QByteArray SimMc1AsciiLine::answer(const QByteArray& line) {
    const std::optional<Mc1AsciiRequest> request = parseMc1AsciiRequest(line);
    if (!request) return "ERR";
    if (request->target == Mc1AsciiRequest::Target::Variable) {
        if (!request->value) return QByteArray::number(m_controller.variable(request->number));
        if (*request->value < kMc1Ascii24Min || *request->value > kMc1Ascii24Max) return "ERR";
        m_controller.setVariable(request->number, *request->value);
        return "OK";
    }
    const Result<Mc1BitAddress> address = mc1BitAddress(request->point, false);
    if (!address) return "ERR";
    if (!request->value) {
        const quint8 byte = address->external
                                ? m_controller.externalByte(address->page, address->address)
                                : m_controller.internalByte(address->address);
        return (byte & address->mask()) ? "1" : "0";
    }
    if (request->point.area == Mc1Area::Input || (*request->value != 0 && *request->value != 1))
        return "ERR";
    m_controller.setBit(*address, *request->value == 1);
    return "OK";
}

}  // namespace cambench::comm
