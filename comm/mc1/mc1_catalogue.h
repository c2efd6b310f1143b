#pragma once

#include "mc1_telegram.h"
#include "mc1_variant.h"

#include "model/result.h"

#include <QByteArray>
#include <QList>

namespace cambench::comm {

// Every MC-1 telegram the client sends (docs/protocols/mc1.md, chapter 3 of
// the manual), one row each in mc1_catalogue.cpp with the variants that
// know it. RDBIT_INT/EXT are left out: nothing about them is printed but
// the opcodes, and RDBYTE does the same.
enum class Mc1Op {
    ReadVariable,   // RDVAR C3 (24-bit answer 04 on an MC100, 32-bit 05 on an MC200)
    WriteVariable,  // WRVAR CE, 24 bit
    WriteVariable32,
    ReadByteInternal,
    WriteByteInternal,
    WriteBitInternal,
    ReadByteExternal,
    WriteByteExternal,
    WriteBitExternal,
    ReadBlock,    // RDBLOCK D5 (MC100 V2)
    ReadMemory6,  // RDMEM6 D5 (MC200): the same opcode, another telegram
    ReadStatus,   // RDSTAT E3 (MC200)
    WriteStatus,
    ReadTable,  // RDTABLE E5 (MC200): logical to physical axis
    ReadMemory,
    WriteMemory,
    ProgramStatus,  // SYSDATA0 92 00 → 94 flags, PC
    ProgramStart,
    ProgramStop,
    ProgramStep,
    ProgramDelete,
    EndOfTransfer,
    UdbAddress,  // SYSDATA0 92 08 → 95 u32
    Reset,       // SYSDATA1 93 05
    PrepareTransfer,
    Flash,            // SYSDATA1 93 0A: 1 save, 2 load
    Display,          // SYSDATA4 96 09
    AxisCommand,      // AXIS_NODATA 9B
    AxisDataCommand,  // AXIS_DATA 9F
};

// Whether a telegram may be sent again after its answer was lost. MC-1 has
// no sequence numbers: the device cannot tell a repeat from a new command.
enum class Mc1Retry {
    Read,        // changes nothing: send again
    Idempotent,  // sets an absolute state: again leaves the same state
    Never,       // acts (start, step, reset, a move, a bit): re-read the state, report
};

struct Mc1Telegram {
    Mc1Op op;
    const char* name;  // as the manual names it ("RDVAR")
    quint8 opcode;
    int command;          // SYSDATA's command byte, -1 none
    int requestData;      // bytes after opcode, checksum (and command); -1: WRMEM's 3 + n
    quint8 answerOpcode;  // kMc1Ack: the single byte 0x80
    int answerData;       // bytes after the answer's opcode and checksum; -1: the n asked for
    Mc1Retry retry;
    bool lengthException;     // the telegram breaks the (opcode & 7) + 1 rule, as printed
    const char* provisional;  // docs/protocols/mc1.md provisional point, or nullptr
};

// The telegrams `variant` knows.
QList<Mc1Telegram> mc1Catalogue(Mc1Variant variant);
// The row of `op` for `variant`, nullptr when the variant lacks it.
const Mc1Telegram* mc1Find(Mc1Variant variant, Mc1Op op);

// The controller's side: the row a request starting with `opcode` (and,
// for SYSDATA, `command`) means on `variant`, nullptr when it means none.
const Mc1Telegram* mc1FindByOpcode(Mc1Variant variant, quint8 opcode, int command);
// Whether requests with this opcode carry a command byte that picks the
// telegram (SYSDATA), as the table says.
bool mc1HasCommandByte(quint8 opcode);
// The row the request `telegram` (whole, or its first bytes) means on
// `variant`; nullptr when it means none or its command byte has not come.
const Mc1Telegram* mc1RequestRow(Mc1Variant variant, const QByteArray& telegram);

// Axis commands differ in what a repeat does: a stop (AXIS_NODATA 08, 09),
// an error acknowledgement (11) and setting override, speed, ramp or a
// preloaded absolute position (AXIS_DATA 0A, 0C, 0D, 02) leave the same
// state; every start or move acts again.
Mc1Retry mc1AxisRetry(Mc1Op op, quint8 command);

// Whether a telegram can start or continue motion or change what the PLC
// program works with (issue 35): every axis command but the stops (AXIS_NODATA
// 08, 09), the program's start, step, reset and flash load, and every write
// (variables, flags, outputs, memory: a restore's writes). The request
// engine refuses it for a job asked before the last STOP.
bool mc1MayMove(Mc1Op op, quint8 command);

// The request for `telegram` with its parameters (after the command byte,
// which is added): refused when their count does not fit the row.
Result<QByteArray> mc1Request(const Mc1Telegram& telegram, const QByteArray& parameters);

// What answers a request: its opcode and whole length (1 for the ACK).
struct Mc1Expectation {
    quint8 opcode = kMc1Ack;
    int length = 1;
    // While the variant is being probed, RDVAR's answer of the other width
    // (04 on an MC100, 05 on an MC200) is taken too: 0 = none.
    quint8 otherOpcode = 0;
    int otherLength = 0;
};
Mc1Expectation mc1ExpectedAnswer(const Mc1Telegram& telegram, const QByteArray& parameters);

// An answer taken from the line.
struct Mc1Answer {
    enum class Kind { Ack, Nak, Data };
    Kind kind = Kind::Ack;
    QByteArray data;  // Data: the bytes after opcode and checksum
};

// Takes the answer to `expected` from the front of `buffer` (bytes read so
// far): 0xFF synchronisation bytes before it are skipped; an ACK or NAK is
// one byte; a data answer is complete at its length and its checksum is
// checked. Returns nothing while the answer is incomplete; an error for a
// byte that starts no answer to this request or a bad checksum (the
// buffer is then cleared: what follows cannot be trusted).
std::optional<Result<Mc1Answer>> takeMc1Answer(QByteArray& buffer, const Mc1Expectation& expected);

}  // namespace cambench::comm
