#include "mc1_telegram.h"

namespace cambench::comm {

quint8 mc1Checksum(const QByteArray& telegram) {
    quint8 sum = 0;
    for (qsizetype i = 0; i < telegram.size(); ++i)
        if (i != 1) sum = quint8(sum + quint8(telegram.at(i)));
    return sum;
}

QByteArray mc1Telegram(quint8 opcode, const QByteArray& data) {
    QByteArray telegram;
    telegram.reserve(data.size() + 2);
    telegram.append(char(opcode));
    telegram.append(char(0));
    telegram.append(data);
    telegram[1] = char(mc1Checksum(telegram));
    return telegram;
}

int mc1FormulaLength(quint8 opcode) {
    return (opcode & 7) + 1;
}

QByteArray mc1LittleEndian(qint64 value, int bytes) {
    QByteArray out;
    const quint64 raw = quint64(value);
    for (int i = 0; i < bytes; ++i) out.append(char((raw >> (8 * i)) & 0xFF));
    return out;
}

qint64 mc1FromLittleEndian(const QByteArray& bytes, bool isSigned) {
    quint64 raw = 0;
    for (qsizetype i = 0; i < bytes.size(); ++i) raw |= quint64(quint8(bytes.at(i))) << (8 * i);
    const int bits = int(bytes.size()) * 8;
    if (isSigned && bits > 0 && bits < 64 && (raw >> (bits - 1)) & 1) raw |= ~quint64(0) << bits;
    return qint64(raw);
}

}  // namespace cambench::comm
