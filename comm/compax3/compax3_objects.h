#pragma once

// The objects and bits CamBench itself uses on a Compax3
// (docs/protocols/compax3.md). All of them come from a public client, not from Parker's manual:
// provisional, and kept here in one place (the table in README.md says
// the same).

#include "model/compax3/compax3_object.h"

#include <QString>
#include <QStringList>

namespace cambench::comm {

inline constexpr Compax3ObjectId kCompax3Serial{1, 4};
inline constexpr Compax3ObjectId kCompax3LastError{550, 1};
inline constexpr Compax3ObjectId kCompax3Position{680, 5};
inline constexpr Compax3ObjectId kCompax3StatusWord{1000, 3};
inline constexpr Compax3ObjectId kCompax3LastSet{1000, 4};
inline constexpr Compax3ObjectId kCompax3ControlWord{1100, 3};
inline constexpr int kCompax3StoreSetsValue = 0x32;  // 1904.n = $32 stores set n
inline constexpr int kCompax3LastSetNumber = 31;     // b8–12 of the control word

// Objects of positioning set n (190x.n).
inline Compax3ObjectId compax3SetTarget(int n) {
    return {1901, n};
}
inline Compax3ObjectId compax3SetVelocity(int n) {
    return {1902, n};
}
// Writing $32 stores set n in the drive's flash (as the public client does
// after a set's values; provisional).
inline Compax3ObjectId compax3StoreSet(int n) {
    return {1904, n};
}
inline Compax3ObjectId compax3SetMode(int n) {
    return {1905, n};
}
inline Compax3ObjectId compax3SetAcceleration(int n) {
    return {1906, n};
}
inline Compax3ObjectId compax3SetDeceleration(int n) {
    return {1907, n};
}

// Control word 1100.3.
namespace compax3control {
inline constexpr quint16 kOff = 0x0000;     // powerless
inline constexpr quint16 kEnable = 0x0001;  // b0: powered; its rising edge acknowledges
// STOP of a powered drive: b0 held at 1 (no edge), the stop bits b1 and b14
// cleared (stop with the ramp), jog, set and start bits 0. The same word as
// kEnable: only what the drive held before makes it a stop, not an enable.
inline constexpr quint16 kStop = 0x0001;
inline constexpr quint16 kRun = 0x4003;  // b0 + stop bits b1, b14 (1 = run)
inline constexpr quint16 kJogPlus = 0x0004;
inline constexpr quint16 kJogMinus = 0x0008;
inline constexpr quint16 kStart = 0x2000;  // b13: a rising edge starts the set
inline constexpr int kSetShift = 8;        // b8–12: the set number
// Run with set n selected, without and with the start bit.
inline quint16 select(int set) {
    return quint16(kRun | (set << kSetShift));
}
inline quint16 start(int set) {
    return quint16(select(set) | kStart);
}
}  // namespace compax3control

// Status word 1000.3, decoded.
struct Compax3StatusWord {
    quint16 word = 0;
    int inputs() const { return word & 0xFF; }  // I0–I7
    bool noError() const { return word & 0x0100; }
    bool positionReached() const { return word & 0x0200; }
    bool powerless() const { return word & 0x0400; }
    bool poweredStandstill() const { return word & 0x0800; }
    bool zeroKnown() const { return word & 0x1000; }
    int psb() const { return (word >> 13) & 0x7; }
};

// One lamp of the status word: bit, its name, whether it is on.
struct Compax3StatusBit {
    int bit;
    QString name;
    bool on;
};
// Every bit of the word with its name, b0 first.
QList<Compax3StatusBit> compax3StatusBits(quint16 word);

// The last error (550.1) in words: "no error", "following error ($7320)";
// unknown codes as "error 12345 ($3039): see the drive's manual".
QString compax3LastErrorText(int code);

}  // namespace cambench::comm
