#include "break_marks.h"

namespace cambench::comm {

QByteArray escapeBreakMarks(const QByteArray& bytes) {
    QByteArray out;
    for (char c : bytes) {
        out += c;
        if (quint8(c) == 0xFF) out += c;
    }
    return out;
}

QList<MarkedRead> takeBreakMarked(QByteArray& pending) {
    QList<MarkedRead> reads;
    QByteArray data;
    int i = 0;
    const auto flush = [&] {
        if (data.isEmpty()) return;
        reads << MarkedRead{MarkedRead::Data, data};
        data.clear();
    };
    while (i < pending.size()) {
        const quint8 c = quint8(pending.at(i));
        if (c != 0xFF) {
            data += char(c);
            ++i;
            continue;
        }
        if (i + 1 >= pending.size()) break;  // FF alone: its partner is still coming
        if (quint8(pending.at(i + 1)) == 0xFF) {
            data += char(0xFF);
            i += 2;
            continue;
        }
        if (i + 2 >= pending.size()) break;
        // FF 00 00: a break. (FF 00 x: a byte with a parity or framing
        // error, taken as a break-like disturbance too.)
        flush();
        reads << MarkedRead{MarkedRead::Break, {}};
        i += 3;
    }
    flush();
    pending.remove(0, i);
    return reads;
}

}  // namespace cambench::comm
