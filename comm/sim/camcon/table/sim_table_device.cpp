#include "sim_table_device.h"

#include "comm/camcon/table/short_commands.h"
#include "comm/sim/camcon/sim_device.h"
#include "comm/sim/sim_log.h"

namespace cambench::comm {

using table::Rk512Error;

SimTableDevice::SimTableDevice(SimDevice& device, table::Rk512Variant variant)
    : m_device(device), m_variant(variant), m_areas(device) {}

std::optional<QByteArray> SimTableDevice::execute(const QByteArray& telegram) {
    if (table::isShortCommandTelegram(telegram)) return executeShort(telegram);
    return executeRk512(telegram);
}

std::optional<QByteArray> SimTableDevice::executeRk512(const QByteArray& telegram) {
    const table::Rk512ParsedRequest parsed = table::parseRk512Request(telegram, m_variant);
    if (!parsed.request) {
        qCDebug(commSimLog) << "RK512 request refused:" << parsed.detail;
        return table::encodeRk512Reply(parsed.error);
    }
    const table::Rk512Request& request = *parsed.request;
    const int offsetsPerWord = table::rk512VariantInfo(m_variant).offsetsPerWord;
    // e38 counts 16-bit words; the simulator keeps whole 32-bit table words.
    if (request.offset % offsetsPerWord != 0 || request.words16 % 2 != 0) {
        qCDebug(commSimLog) << "RK512 request for half a table word refused";
        return table::encodeRk512Reply(Rk512Error::General);
    }
    const int firstWord = request.offset / offsetsPerWord;
    const int count = request.words16 / 2;
    qCDebug(commSimLog) << "RK512" << (request.order == table::Rk512Order::Read ? "read" : "write")
                        << "area" << request.area << "words" << firstWord << "+" << count;
    if (request.order == table::Rk512Order::Read) {
        const SimAreaReply reply = m_areas.read(request.area, firstWord, count);
        if (reply.error != Rk512Error::None) {
            qCDebug(commSimLog) << "refused:" << reply.detail;
            return table::encodeRk512Reply(reply.error);
        }
        return table::encodeRk512Reply(Rk512Error::None, table::tableWordsToBytes(reply.words));
    }
    const Result<QList<qint32>> values = table::bytesToTableWords(request.data);
    if (!values) return table::encodeRk512Reply(Rk512Error::General);
    const SimAreaReply reply = m_areas.write(request.area, firstWord, *values);
    if (reply.silent) return std::nullopt;
    if (reply.error != Rk512Error::None) qCDebug(commSimLog) << "refused:" << reply.detail;
    return table::encodeRk512Reply(reply.error);
}

}  // namespace cambench::comm
