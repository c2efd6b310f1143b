#include "cambus_payload.h"

#include <QCoreApplication>

namespace cambench::comm {

QByteArray camBusPayload(char lead, QByteArrayView body) {
    QByteArray data;
    data += lead;
    data += body.toByteArray();
    data += checksumText(checksum(lead, body));
    return data;
}

Result<Frame> parseCamBusPayload(const QByteArray& data) {
    if (data.size() < 3)
        return Error::invalidData(
            QCoreApplication::translate("cambench::comm",
                                        "a Cam-BUS block of %1 bytes holds no CamCon frame")
                .arg(data.size()));
    const char lead = data.at(0);
    if (lead != kQuery && lead != kCommand && lead != kReply)
        return Error::invalidData(
            QCoreApplication::translate("cambench::comm",
                                        "a Cam-BUS block that does not start with ?, ! or : "
                                        "(0x%1)")
                .arg(quint8(lead), 2, 16, QLatin1Char('0')));
    const QByteArray body = data.mid(1, data.size() - 3);
    const QByteArray sent = data.right(2);
    const QByteArray expected = checksumText(checksum(lead, body));
    if (sent.toUpper() != expected)
        return Error::invalidData(
            QCoreApplication::translate("cambench::comm",
                                        "a frame in a Cam-BUS block with checksum %1, not %2")
                .arg(QString::fromLatin1(sent), QString::fromLatin1(expected)));
    return Frame{lead, body, std::nullopt, true};
}

}  // namespace cambench::comm
