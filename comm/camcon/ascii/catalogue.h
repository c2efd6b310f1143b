#pragma once

#include "comm/engine/request.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QList>

namespace cambench::comm {

// How one field is written on the wire (notes 2).
enum class FieldType {
    Hex,        // unsigned, `width` upper-case hex digits
    SignedHex,  // two's complement in `width` hex digits
    Text,       // `width` raw characters including the NUL, padded with NUL
    TextRest,   // raw characters up to the checksum (e.g. the :AUTO display text)
    Binary,     // `width` raw bytes; width -1 = up to the checksum (EEPROM blocks)
    HexBytes,   // status tables: 2 hex digits per 8 bits, up to the checksum
    HexWords,   // `count` words of `width` hex digits each (PLC symbol fields)
};
// A field that runs "up to the checksum" (TextRest, HexBytes, Binary -1,
// HexWords count -1) is always the last one of its list.

struct FieldSpec {
    const char* name;
    FieldType type;
    int width;      // characters for Hex/SignedHex/Text/HexWords, bytes for Binary, -1 = rest
    int count = 1;  // HexWords only; -1 = as many words as the data holds (?ANTAB)
};

enum class ReplyKind {
    Data,  // ':' + name + reply fields
    Ok,    // ':' + name + "OK"
    None,  // no reply at all (!GRESET)
};

// One command of manual section 5, from which encoding and decoding follow.
struct CommandSpec {
    char kind;                 // '?' or '!'
    const char* name;          // command letters, e.g. "NF"
    QList<FieldSpec> request;  // data after the name
    ReplyKind replyKind;
    QList<FieldSpec> reply;  // for ReplyKind::Data
    const char* section;     // manual section, e.g. "5.2.1.1"
    // Where a guessed format comes from ("provisional: P-ASCII-2, …", the
    // ids of comm/camcon/README.md); nullptr for a manual page's format.
    const char* provisional = nullptr;
    TimeoutClass timeout = TimeoutClass::Normal;
    QList<QByteArray> replyAliases{};  // other names the reply may carry (?MEES -> :MSE)
    bool okOptional = false;           // the reply may lack "OK" (!GTZKANZ, notes 10)
    // Whether a retry after a lost reply is safe in Standard framing, where
    // the device executes a repeated request again (Multiuser answers it).
    RetryPolicy retry = RetryPolicy::Idempotent;
};

// Every command of manual section 5 (and the provisional ones of the notes).
const QList<CommandSpec>& commandCatalogue();

// nullptr when the catalogue has no such command.
const CommandSpec* findCommand(char kind, QByteArrayView name);

// The command a request body starts with: the longest catalogue name that
// prefixes `body` for that kind ("NFxxxx..." -> NF). Used by the simulator.
const CommandSpec* matchRequest(char kind, QByteArrayView body);

}  // namespace cambench::comm
