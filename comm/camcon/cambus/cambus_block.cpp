#include "cambus_block.h"

#include <QCoreApplication>

namespace cambench::comm {

QByteArray camBusToken(int user) {
    const char s = char(camBusByte(CamBusByteKind::Did, user));
    return QByteArray() + char(kCamBusToken1) + char(kCamBusToken2) + s + s;
}

quint16 camBusSum(const QByteArray& lenAndData) {
    quint32 sum = 0;
    for (char c : lenAndData) sum += quint8(c);
    return quint16(sum & 0x7FFF);
}

Result<QByteArray> encodeCamBusBlock(const CamBusBlock& block) {
    if (block.data.isEmpty() || block.data.size() > kCamBusMaxData)
        return Error::usage(QCoreApplication::translate(
                                "cambench::comm", "a Cam-BUS block holds 1 to 255 bytes, not %1")
                                .arg(block.data.size()));
    QByteArray wire;
    wire += char(block.data.size());
    wire += block.data;
    const quint16 sum = camBusSum(wire);
    wire += char((block.blockBit ? 0x80 : 0x00) | (sum >> 8));
    wire += char(sum & 0xFF);
    return wire;
}

Result<std::optional<CamBusBlock>> takeCamBusBlock(QByteArray& bytes) {
    if (bytes.isEmpty()) return std::optional<CamBusBlock>();
    const int length = quint8(bytes.at(0));
    if (length == 0) {
        bytes.remove(0, 1);
        return Error::invalidData(
            QCoreApplication::translate("cambench::comm", "a Cam-BUS block with LEN 0"));
    }
    if (bytes.size() < length + 3) return std::optional<CamBusBlock>();
    const QByteArray lenAndData = bytes.left(length + 1);
    const quint8 chk1 = quint8(bytes.at(length + 1));
    const quint8 chk2 = quint8(bytes.at(length + 2));
    bytes.remove(0, length + 3);
    const quint16 sum = camBusSum(lenAndData);
    const quint16 got = quint16(((chk1 & 0x7F) << 8) | chk2);
    if (got != sum)
        return Error::invalidData(
            QCoreApplication::translate("cambench::comm",
                                        "a Cam-BUS block whose checksum is %1, not %2")
                .arg(got, 4, 16, QLatin1Char('0'))
                .arg(sum, 4, 16, QLatin1Char('0')));
    CamBusBlock block;
    block.data = lenAndData.mid(1);
    block.blockBit = chk1 & 0x80;
    return std::optional<CamBusBlock>(block);
}

}  // namespace cambench::comm
