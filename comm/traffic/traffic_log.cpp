#include "traffic_log.h"

namespace cambench::comm {

QString formatTrafficEntry(const TrafficEntry& entry) {
    QString ascii;
    ascii.reserve(entry.bytes.size());
    for (const char c : entry.bytes) {
        const auto byte = static_cast<unsigned char>(c);
        ascii += (byte >= 0x20 && byte < 0x7F) ? QChar(byte) : QChar(u'.');
    }
    return QStringLiteral("%1 %2 %3  |%4|")
        .arg(entry.time.toString(QStringLiteral("yyyy-MM-ddTHH:mm:ss.zzz")),
             entry.outgoing ? QStringLiteral(">") : QStringLiteral("<"),
             QString::fromLatin1(entry.bytes.toHex(' ').toUpper()), ascii);
}

}  // namespace cambench::comm
