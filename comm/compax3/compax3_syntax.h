#pragma once

// The Compax3 ASCII protocol's text (docs/protocols/compax3.md): requests as
// CamBench sends them and answers as the drive gives them. No line, no
// timing: the backend and the simulator both use this.

#include "model/compax3/compax3_object.h"
#include "model/compax3/compax3_refusals.h"
#include "model/result.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace cambench::comm {

constexpr char kCompax3End = '\r';
constexpr char kCompax3Rs485Mark = '*';  // before every RS485 answer (Parker: 2-wire only)
constexpr int kCompax3LastAddress = 99;

// "O680,5" / "O680,5$" (answer in hexadecimal): the manual's form, with ','.
QByteArray compax3ReadCommand(const Compax3ObjectId& id, bool hexAnswer = false);
// "O1901,1=12.5": `wireValue` as compax3WireValue made it.
QByteArray compax3WriteCommand(const Compax3ObjectId& id, const QString& wireValue);
// The info string's command.
QByteArray compax3InfoCommand();
// A whole request line: the address first on RS485 (0..99, decimal), CR last.
QByteArray compax3RequestLine(const QByteArray& command, int address);

// One answer line without its CR (and without the RS485 '*').
struct Compax3Reply {
    enum Kind {
        Value,  // a number or text: `text`
        Ok,     // '>': a write or function taken
        Error,  // '!xxxx': refused, `code` the four hex digits
    };
    Kind kind = Value;
    QString text;
    int code = 0;
};

// An answer line, '*' in front accepted (RS485) or not (RS232, Parker's
// 4-wire RS485). A malformed one ("!12", bytes outside 0x20..0x7E) fails
// with InvalidData saying what arrived.
Result<Compax3Reply> parseCompax3Reply(const QByteArray& line);

// Whether a refusal says the drive does not have the object (!0002 "no
// such object" in the table of refusals, provisional): the object is "not on this drive", which a
// backup records instead of failing.
// Without a table: the shipped one; with one: the dictionary's in use.
bool compax3RefusalMeansAbsent(const cambench::Error& error);
bool compax3RefusalMeansAbsent(const cambench::Error& error,
                               const cambench::Compax3RefusalTable& table);
// "the drive refused O1901,1=5 with !0004 (the value is outside …)", the
// meaning from `table` (the dictionary in use; without one the shipped).
cambench::Error compax3RefusalError(const QByteArray& command, int code);
cambench::Error compax3RefusalError(const QByteArray& command, int code,
                                    const cambench::Compax3RefusalTable& table);

// A request as the drive reads it: upper case, no spaces outside "…"
// (what the drive does to every line before it looks at it).
QByteArray compax3Canonical(const QByteArray& command);

// A parsed request, for the simulator: `O[$]i,[$]s[$]` with or without
// `=value`, or the info command.
struct Compax3Request {
    enum Kind { Read, Write, Info };
    Kind kind = Read;
    Compax3ObjectId id;
    bool hexAnswer = false;
    QString value;  // Write: the text after '='
};
std::optional<Compax3Request> parseCompax3Request(const QByteArray& canonical);

}  // namespace cambench::comm
