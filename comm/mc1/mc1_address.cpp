#include "mc1_address.h"

#include "model/mc1/mc1_backup_file.h"

#include <QRegularExpression>

namespace cambench::comm {

namespace {

// A run of consecutive numbers in one byte: `count` numbers from `first`,
// the first at bit `bit` of `address`.
struct BitRun {
    int first;
    quint8 address;
    int count;
    int bit;
};

// Manual table 47 (internal flags M500–M1088 of the MC100) and table 48
// (special inputs E500–E579), taken from the manual line by line into runs.
// Numbers in no run do not exist (M723, for one, has no address).
const BitRun kFlagRuns[] = {
    {500, 0x2B, 8, 0},  {508, 0x21, 2, 5},  {510, 0x09, 1, 0},  {511, 0x2C, 8, 0},
    {519, 0x65, 8, 0},  {527, 0x66, 8, 0},  {535, 0x67, 8, 0},  {550, 0x23, 1, 4},
    {551, 0xE1, 8, 0},  {559, 0x23, 2, 1},  {561, 0x22, 1, 0},  {562, 0x22, 2, 3},
    {564, 0x22, 2, 6},  {566, 0x23, 1, 0},  {570, 0x23, 1, 3},  {571, 0x23, 1, 7},
    {572, 0x28, 1, 6},  {573, 0x21, 1, 0},  {574, 0x20, 1, 7},  {575, 0xE0, 2, 0},
    {580, 0x21, 1, 1},  {588, 0x26, 1, 7},  {589, 0x26, 1, 6},  {590, 0x24, 4, 4},
    {594, 0x25, 2, 0},  {596, 0x25, 4, 4},  {601, 0x58, 8, 0},  {609, 0x59, 8, 0},
    {617, 0x5A, 8, 0},  {625, 0x5B, 8, 0},  {633, 0x5C, 8, 0},  {641, 0x5D, 8, 0},
    {649, 0x5E, 8, 0},  {801, 0xB8, 8, 0},  {809, 0xB9, 8, 0},  {817, 0xBA, 8, 0},
    {825, 0xBB, 8, 0},  {833, 0xBC, 8, 0},  {841, 0xBD, 8, 0},  {849, 0xBE, 8, 0},
    {857, 0xBF, 8, 0},  {865, 0xC0, 8, 0},  {873, 0xC1, 8, 0},  {881, 0xC2, 8, 0},
    {889, 0xC3, 8, 0},  {897, 0xC4, 8, 0},  {905, 0xC5, 8, 0},  {913, 0xC6, 8, 0},
    {921, 0xC7, 8, 0},  {929, 0xCC, 8, 0},  {937, 0xC8, 8, 0},  {945, 0xC9, 8, 0},
    {953, 0xCD, 8, 0},  {1001, 0x60, 8, 0}, {1009, 0x61, 8, 0}, {1017, 0x62, 8, 0},
    {1025, 0xD0, 8, 0}, {1033, 0xD1, 8, 0}, {1041, 0xD2, 8, 0}, {1049, 0xD3, 8, 0},
    {1057, 0xD4, 8, 0}, {1065, 0xD5, 8, 0}, {1073, 0xD6, 8, 0}, {1081, 0xD7, 8, 0},
};
const BitRun kSpecialInputRuns[] = {
    {500, 0xB8, 4, 0}, {504, 0xB9, 4, 0}, {508, 0xBA, 4, 0}, {512, 0xBB, 4, 0}, {516, 0xBC, 4, 0},
    {520, 0xBD, 4, 0}, {524, 0xBE, 4, 0}, {528, 0xBF, 4, 0}, {532, 0xC0, 5, 0}, {537, 0xC1, 5, 0},
    {542, 0xC2, 5, 0}, {547, 0xC3, 5, 0}, {552, 0xC4, 5, 0}, {557, 0xC5, 5, 0}, {562, 0xC6, 5, 0},
    {567, 0xC7, 5, 0}, {572, 0xC8, 4, 0}, {576, 0xC9, 4, 0},
};

template <std::size_t N>
std::optional<Mc1BitAddress> fromRuns(const BitRun (&runs)[N], int number) {
    for (const BitRun& run : runs) {
        if (number >= run.first && number < run.first + run.count)
            return Mc1BitAddress{false, 0, run.address, quint8(run.bit + number - run.first)};
    }
    return std::nullopt;
}

Mc1BitAddress internalAt(int base, int index) {
    return {false, 0, quint8(base + (index >> 3)), quint8(index & 7)};
}

Mc1BitAddress externalAt(quint8 page, int index) {
    return {true, page, quint8(index >> 3), quint8(index & 7)};
}

Error noSuch(const Mc1Point& point, bool mc200, const QString& ranges) {
    return Error::usage(QStringLiteral("%1 does not exist on an %2 (%3)")
                            .arg(mc1PointText(point),
                                 mc200 ? QStringLiteral("MC200") : QStringLiteral("MC100"),
                                 ranges));
}

Result<Mc1BitAddress> mc100(const Mc1Point& point) {
    const int n = point.number;
    switch (point.area) {
        case Mc1Area::Flag:
            // External page 0x7F: 2048 flags fill it, M1–499 then M2000–3548.
            if (n >= 1 && n <= 499) return externalAt(mc1ExternalFlagPage(false), n - 1);
            if (n >= 2000 && n <= 3548) return externalAt(mc1ExternalFlagPage(false), n - 1501);
            if (const auto at = fromRuns(kFlagRuns, n)) return *at;
            return noSuch(point, false,
                          QStringLiteral("flags M1–M499, M500–M1088 as table 47 lists them, "
                                         "M2000–M3548"));
        case Mc1Area::Input:
            // 193–196 share 0xB8 with M801–804 and E500–503, as printed.
            if (n >= 1 && n <= 196) return internalAt(0xA0, n - 1);
            if (const auto at = fromRuns(kSpecialInputRuns, n)) return *at;
            return noSuch(point, false, QStringLiteral("inputs E1–E196, special inputs E500–E579"));
        case Mc1Area::Output:
            if (n >= 1 && n <= 128) return internalAt(0x90, n - 1);
            return noSuch(point, false, QStringLiteral("outputs A1–A128"));
    }
    return Error::usage(QStringLiteral("unknown area"));
}

Result<Mc1BitAddress> mc200(const Mc1Point& point) {
    const int n = point.number;
    switch (point.area) {
        case Mc1Area::Flag:
            if (n >= 1 && n <= 2048) return externalAt(mc1ExternalFlagPage(true), n - 1);
            if (n >= 2049 && n <= 3584) return internalAt(0x00, n - 2049);
            return noSuch(point, true, QStringLiteral("flags M1–M3584"));
        case Mc1Area::Input:
            if (n >= 1 && n <= 256) return internalAt(0xE0, n - 1);
            return noSuch(point, true, QStringLiteral("inputs E1–E256"));
        case Mc1Area::Output:
            if (n >= 1 && n <= 256) return internalAt(0xC0, n - 1);
            return noSuch(point, true, QStringLiteral("outputs A1–A256"));
    }
    return Error::usage(QStringLiteral("unknown area"));
}

}  // namespace

Result<Mc1Point> parseMc1Point(const QString& text) {
    static const QRegularExpression pattern(QStringLiteral("^\\s*([MEAmea])\\s*(\\d{1,5})\\s*$"));
    const QRegularExpressionMatch match = pattern.match(text);
    if (!match.hasMatch())
        return Error::usage(
            QStringLiteral("\"%1\" is no flag, input or output: write M2327, E122 or A122")
                .arg(text));
    const QChar letter = match.captured(1).at(0).toUpper();
    const Mc1Area area = letter == QLatin1Char('M')   ? Mc1Area::Flag
                         : letter == QLatin1Char('E') ? Mc1Area::Input
                                                      : Mc1Area::Output;
    return Mc1Point{area, match.captured(2).toInt()};
}

QString mc1PointText(const Mc1Point& point) {
    const char letter = point.area == Mc1Area::Flag    ? 'M'
                        : point.area == Mc1Area::Input ? 'E'
                                                       : 'A';
    return QStringLiteral("%1%2").arg(QLatin1Char(letter)).arg(point.number);
}

Result<Mc1BitAddress> mc1BitAddress(const Mc1Point& point, bool isMc200) {
    return isMc200 ? mc200(point) : mc100(point);
}

QList<int> mc1PointNumbers(Mc1Area area, bool isMc200) {
    QList<int> numbers;
    // The highest number any table names: M3584 (MC200), E579 (MC100).
    const int highest = area == Mc1Area::Flag ? 3584 : area == Mc1Area::Input ? 579 : 256;
    for (int n = 1; n <= highest; ++n)
        if (mc1BitAddress(Mc1Point{area, n}, isMc200).ok()) numbers << n;
    return numbers;
}

quint8 mc1ExternalFlagPage(bool isMc200) {
    return isMc200 ? 0x00 : 0x7F;
}

Mc1Point mc1ExternalFlagAt(int index, bool isMc200) {
    // MC100: M1–499 then M2000–3548 (the inverse of mc100() above); the
    // backup file names its flags the same way.
    return {Mc1Area::Flag, mc1ExternalFlagNumber(index, isMc200)};
}

}  // namespace cambench::comm
