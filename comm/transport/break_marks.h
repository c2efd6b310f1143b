#pragma once

#include <QByteArray>
#include <QList>

namespace cambench::comm {

// Breaks inside the byte stream, as Linux marks them with PARMRK: a break
// reads FF 00 00 and a data byte FF reads FF FF. A protocol that sends and
// hears breaks (Cam-BUS) speaks this encoding on every transport; a real
// serial port turns it into real breaks (SerialSettings::inBandBreaks), a
// pseudo-terminal or the simulator carry it as it is (docs/protocols/cambus.md P12).

// Data bytes in the encoding: every FF doubled.
QByteArray escapeBreakMarks(const QByteArray& bytes);

// A piece of marked input: data (FF FF made FF again) or one break.
struct MarkedRead {
    enum Kind { Data, Break };
    Kind kind = Data;
    QByteArray data;
};
// What `pending` holds, split into data and breaks, in order, and taken
// out of it; an FF at the end (its partner not here yet) stays.
QList<MarkedRead> takeBreakMarked(QByteArray& pending);

}  // namespace cambench::comm
