#pragma once

#include "model/result.h"

#include <QList>
#include <QString>

namespace cambench::comm {

// The one place of the MC-1 address arithmetic (docs/protocols/mc1.md,
// "Memory"; manual chapters 4 and 5): where a flag (M), input (E) or output
// (A) of its manual number lives, read with RDBYTE and written with WRBIT.
enum class Mc1Area { Flag, Input, Output };

struct Mc1Point {
    Mc1Area area = Mc1Area::Flag;
    int number = 1;  // as the manual and the controller's program name it
    friend bool operator==(const Mc1Point& a, const Mc1Point& b) {
        return a.area == b.area && a.number == b.number;
    }
};

// Where it is: internal RAM (address) or external RAM (page, address), and
// its bit.
struct Mc1BitAddress {
    bool external = false;
    quint8 page = 0;  // external only
    quint8 address = 0;
    quint8 bit = 0;  // 0..7
    quint8 mask() const { return quint8(1u << bit); }
    friend bool operator==(const Mc1BitAddress& a, const Mc1BitAddress& b) {
        return a.external == b.external && a.page == b.page && a.address == b.address &&
               a.bit == b.bit;
    }
};

// "M2327", "E122", "A122" (case and spaces ignored).
Result<Mc1Point> parseMc1Point(const QString& text);
// "M2327".
QString mc1PointText(const Mc1Point& point);

// The address of `point` on an MC100 (`mc200` false) or MC200; an error
// names the numbers that exist. MC100: flags M1–499 and M2000–3548 external
// (page 0x7F), M500–1088 internal by table 47 (with its gaps), inputs 1–196
// and special inputs E500–579 (table 48), outputs 1–128. MC200: flags
// M1–2048 external (page 0), M2049–3584 internal, inputs and outputs 1–256.
Result<Mc1BitAddress> mc1BitAddress(const Mc1Point& point, bool mc200);

// Every number of `area` that exists on an MC100 or MC200, ascending.
QList<int> mc1PointNumbers(Mc1Area area, bool mc200);
// The external RAM page of the flags that live there (MC100 0x7F, MC200 0).
quint8 mc1ExternalFlagPage(bool mc200);
// The flag at bit `index` (byte index >> 3, bit index & 7) of that page:
// every one of its 2048 bits is a flag on both controllers.
Mc1Point mc1ExternalFlagAt(int index, bool mc200);

}  // namespace cambench::comm
