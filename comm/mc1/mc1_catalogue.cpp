#include "mc1_catalogue.h"

#include <QString>

namespace cambench::comm {

namespace {

// Which variants know a row.
enum VariantMask : unsigned {
    M100V1 = 1,
    M100V2 = 2,
    M200V1 = 4,
    M200V2 = 8,
    MC100 = M100V1 | M100V2,
    MC200 = M200V1 | M200V2,
    ALL = MC100 | MC200,
};

struct Row {
    unsigned variants;
    Mc1Telegram telegram;
};

constexpr int kN = -1;  // a length that depends on the request
constexpr quint8 ACK = kMc1Ack;
constexpr auto READ = Mc1Retry::Read;
constexpr auto SAME = Mc1Retry::Idempotent;
constexpr auto NEVER = Mc1Retry::Never;
const char* const kP1 = "P1: 16-bit memory address as the tables print (the length rule wants 32)";
const char* const kP2 = "P2: WRBYTE layout (only the opcode is printed)";
const char* const kP3 = "P3: CE on an MC200 sign-extends the 24-bit value";

// Manual chapter 3 and docs/protocols/mc1.md. Columns: variants | op, name,
// opcode, command byte, request data, answer opcode, answer data, retry,
// length exception, provisional point.
const Row kRows[] = {
    {MC100, {Mc1Op::ReadVariable, "RDVAR", 0xC3, -1, 2, 0x04, 3, READ, false, nullptr}},
    {MC200, {Mc1Op::ReadVariable, "RDVAR", 0xC3, -1, 2, 0x05, 4, READ, false, nullptr}},
    {ALL, {Mc1Op::WriteVariable, "WRVAR", 0xCE, -1, 5, ACK, 0, SAME, false, kP3}},
    {MC200, {Mc1Op::WriteVariable32, "WRVAR", 0xCF, -1, 6, ACK, 0, SAME, false, nullptr}},
    {ALL, {Mc1Op::ReadByteInternal, "RDBYTE_INT", 0x22, -1, 1, 0x02, 1, READ, false, nullptr}},
    {ALL, {Mc1Op::WriteByteInternal, "WRBYTE_INT", 0x2B, -1, 2, ACK, 0, SAME, false, kP2}},
    // WRBIT sets or clears one bit: the rule keeps it from blind repeats.
    {ALL, {Mc1Op::WriteBitInternal, "WRBIT_INT", 0x3B, -1, 2, ACK, 0, NEVER, false, nullptr}},
    {ALL, {Mc1Op::ReadByteExternal, "RDBYTE_EXT", 0xA3, -1, 2, 0x02, 1, READ, false, nullptr}},
    {ALL, {Mc1Op::WriteByteExternal, "WRBYTE_EXT", 0xAC, -1, 3, ACK, 0, SAME, false, kP2}},
    {ALL, {Mc1Op::WriteBitExternal, "WRBIT_EXT", 0xBB, -1, 2, ACK, 0, NEVER, false, nullptr}},
    {M100V2, {Mc1Op::ReadBlock, "RDBLOCK", 0xD5, -1, 4, 0xD7, kN, READ, true, nullptr}},
    {MC200, {Mc1Op::ReadMemory6, "RDMEM6", 0xD5, -1, 2, 0xD7, 6, READ, true, kP1}},
    {MC200, {Mc1Op::ReadStatus, "RDSTAT", 0xE3, -1, 2, 0xE5, 4, READ, false, nullptr}},
    {MC200, {Mc1Op::WriteStatus, "WRSTAT", 0xEF, -1, 6, ACK, 0, SAME, false, nullptr}},
    {MC200, {Mc1Op::ReadTable, "RDTABLE", 0xE5, -1, 4, 0xE3, 2, READ, false, nullptr}},
    {M200V2, {Mc1Op::ReadMemory, "RDMEM", 0xD6, -1, 3, 0xD0, kN, READ, true, kP1}},
    {M200V2, {Mc1Op::WriteMemory, "WRMEM", 0xDE, -1, kN, ACK, 0, SAME, true, kP1}},
    {M200V2,
     {Mc1Op::ProgramStatus, "SYSDATA status", 0x92, 0x00, 0, 0x94, 3, READ, false, nullptr}},
    {M200V2, {Mc1Op::ProgramStart, "SYSDATA start", 0x92, 0x01, 0, ACK, 0, NEVER, false, nullptr}},
    // Stopping twice leaves the program stopped: a lost answer may be repeated.
    {M200V2, {Mc1Op::ProgramStop, "SYSDATA stop", 0x92, 0x02, 0, ACK, 0, SAME, false, nullptr}},
    {M200V2, {Mc1Op::ProgramStep, "SYSDATA step", 0x92, 0x03, 0, ACK, 0, NEVER, false, nullptr}},
    {M200V2,
     {Mc1Op::ProgramDelete, "SYSDATA delete", 0x92, 0x04, 0, ACK, 0, NEVER, false, nullptr}},
    {M200V2,
     {Mc1Op::EndOfTransfer, "SYSDATA end of transfer", 0x92, 0x07, 0, ACK, 0, NEVER, false,
      nullptr}},
    {M200V2,
     {Mc1Op::UdbAddress, "SYSDATA UDB address", 0x92, 0x08, 0, 0x95, 4, READ, false, nullptr}},
    {M200V2, {Mc1Op::Reset, "SYSDATA reset", 0x93, 0x05, 1, ACK, 0, NEVER, false, nullptr}},
    {M200V2,
     {Mc1Op::PrepareTransfer, "SYSDATA prepare transfer", 0x93, 0x06, 1, ACK, 0, NEVER, false,
      nullptr}},
    {M200V2, {Mc1Op::Flash, "SYSDATA flash", 0x93, 0x0A, 1, ACK, 0, NEVER, false, nullptr}},
    {M200V2, {Mc1Op::Display, "SYSDATA display", 0x96, 0x09, 4, ACK, 0, NEVER, false, nullptr}},
    {M200V2, {Mc1Op::AxisCommand, "AXIS_NODATA", 0x9B, -1, 2, ACK, 0, NEVER, false, nullptr}},
    {M200V2, {Mc1Op::AxisDataCommand, "AXIS_DATA", 0x9F, -1, 6, ACK, 0, NEVER, false, nullptr}},
};

unsigned maskOf(Mc1Variant variant) {
    switch (variant) {
        case Mc1Variant::Mc100V1:
            return M100V1;
        case Mc1Variant::Mc100V2:
            return M100V2;
        case Mc1Variant::Mc200V1:
            return M200V1;
        case Mc1Variant::Mc200V2:
            return M200V2;
    }
    return 0;
}

QString hex(quint8 byte) {
    return QStringLiteral("%1").arg(byte, 2, 16, QLatin1Char('0')).toUpper();
}

}  // namespace

QList<Mc1Telegram> mc1Catalogue(Mc1Variant variant) {
    QList<Mc1Telegram> telegrams;
    for (const Row& row : kRows)
        if (row.variants & maskOf(variant)) telegrams << row.telegram;
    return telegrams;
}

const Mc1Telegram* mc1Find(Mc1Variant variant, Mc1Op op) {
    for (const Row& row : kRows)
        if ((row.variants & maskOf(variant)) && row.telegram.op == op) return &row.telegram;
    return nullptr;
}

const Mc1Telegram* mc1FindByOpcode(Mc1Variant variant, quint8 opcode, int command) {
    for (const Row& row : kRows) {
        const Mc1Telegram& t = row.telegram;
        if ((row.variants & maskOf(variant)) && t.opcode == opcode &&
            (t.command < 0 || t.command == command))
            return &t;
    }
    return nullptr;
}

bool mc1HasCommandByte(quint8 opcode) {
    for (const Row& row : kRows)
        if (row.telegram.opcode == opcode && row.telegram.command >= 0) return true;
    return false;
}

const Mc1Telegram* mc1RequestRow(Mc1Variant variant, const QByteArray& telegram) {
    if (telegram.isEmpty()) return nullptr;
    const quint8 opcode = quint8(telegram.at(0));
    if (!mc1HasCommandByte(opcode)) return mc1FindByOpcode(variant, opcode, -1);
    return telegram.size() > 2 ? mc1FindByOpcode(variant, opcode, quint8(telegram.at(2))) : nullptr;
}

Mc1Retry mc1AxisRetry(Mc1Op op, quint8 command) {
    if (op == Mc1Op::AxisCommand)
        return (command == 0x08 || command == 0x09 || command == 0x11) ? Mc1Retry::Idempotent
                                                                       : Mc1Retry::Never;
    if (op == Mc1Op::AxisDataCommand)
        return (command == 0x02 || command == 0x0A || command == 0x0C || command == 0x0D)
                   ? Mc1Retry::Idempotent
                   : Mc1Retry::Never;
    return Mc1Retry::Never;
}

bool mc1MayMove(Mc1Op op, quint8 command) {
    switch (op) {
        case Mc1Op::AxisCommand:
            return command != 0x08 && command != 0x09;
        case Mc1Op::AxisDataCommand:
        case Mc1Op::WriteVariable:
        case Mc1Op::WriteVariable32:
        case Mc1Op::WriteByteInternal:
        case Mc1Op::WriteBitInternal:
        case Mc1Op::WriteByteExternal:
        case Mc1Op::WriteBitExternal:
        case Mc1Op::WriteStatus:
        case Mc1Op::WriteMemory:
        case Mc1Op::ProgramStart:
        case Mc1Op::ProgramStep:
        case Mc1Op::Reset:
        case Mc1Op::Flash:
            return true;
        default:
            return false;
    }
}

Result<QByteArray> mc1Request(const Mc1Telegram& telegram, const QByteArray& parameters) {
    const bool fits =
        telegram.requestData >= 0
            ? parameters.size() == telegram.requestData
            // WRMEM: address u16, n, then n bytes
            : parameters.size() >= 3 && parameters.size() == 3 + quint8(parameters.at(2));
    if (!fits)
        return Error::usage(QStringLiteral("%1 takes %2 parameter bytes, got %3")
                                .arg(QLatin1String(telegram.name))
                                .arg(telegram.requestData >= 0
                                         ? QString::number(telegram.requestData)
                                         : QStringLiteral("3 + n"))
                                .arg(parameters.size()));
    QByteArray data;
    if (telegram.command >= 0) data.append(char(telegram.command));
    data.append(parameters);
    return mc1Telegram(telegram.opcode, data);
}

Mc1Expectation mc1ExpectedAnswer(const Mc1Telegram& telegram, const QByteArray& parameters) {
    if (telegram.answerOpcode == kMc1Ack) return {};
    int data = telegram.answerData;
    if (data < 0) {
        // RDBLOCK: address, page, RAM, n; RDMEM: address u16, n.
        const int at = telegram.op == Mc1Op::ReadBlock ? 3 : 2;
        data = at < parameters.size() ? quint8(parameters.at(at)) : 0;
    }
    return {telegram.answerOpcode, 2 + data};
}

std::optional<Result<Mc1Answer>> takeMc1Answer(QByteArray& buffer, const Mc1Expectation& expected) {
    while (!buffer.isEmpty() && quint8(buffer.at(0)) == kMc1Sync) buffer.remove(0, 1);
    if (buffer.isEmpty()) return std::nullopt;
    const quint8 first = quint8(buffer.at(0));
    if (first == kMc1Ack || first == kMc1Nak) {
        buffer.remove(0, 1);
        return Result<Mc1Answer>(
            Mc1Answer{first == kMc1Ack ? Mc1Answer::Kind::Ack : Mc1Answer::Kind::Nak, {}});
    }
    const bool other = expected.otherOpcode != 0 && first == expected.otherOpcode;
    if ((first != expected.opcode || expected.opcode == kMc1Ack) && !other) {
        const QString got = hex(first);
        buffer.clear();
        return Result<Mc1Answer>(Error::communication(
            QStringLiteral("the answer starts with %1, not with %2 as this request needs")
                .arg(got, expected.opcode == kMc1Ack ? QStringLiteral("80 (ACK) or 87 (NAK)")
                                                     : hex(expected.opcode))));
    }
    const int length = other ? expected.otherLength : expected.length;
    if (buffer.size() < length) return std::nullopt;
    const QByteArray telegram = buffer.left(length);
    buffer.remove(0, length);
    if (mc1Checksum(telegram) != quint8(telegram.at(1))) {
        buffer.clear();
        return Result<Mc1Answer>(Error::communication(
            QStringLiteral("the answer %1 has checksum %2, its bytes add up to %3")
                .arg(QString::fromLatin1(telegram.toHex(' ').toUpper()),
                     hex(quint8(telegram.at(1))), hex(mc1Checksum(telegram)))));
    }
    return Result<Mc1Answer>(Mc1Answer{Mc1Answer::Kind::Data, telegram.mid(2)});
}

}  // namespace cambench::comm
