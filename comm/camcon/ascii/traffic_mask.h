#pragma once

#include <QByteArray>

namespace cambench::comm {

// Overwrites the user numbers (the access codes of manual 5.4.1) in the wire
// bytes of one frame, or the start of one, with '*': the number fields of
// a "!USER" request when `outgoing`, of a ":USER" reply otherwise, and the
// data of EEPROM blocks ("!EE" requests, ":EE" replies), which hold the
// same numbers. Field positions come from the command catalogue; ESC-escaped
// bytes are masked together with their ESC; the checksum stays readable only
// in a whole frame. Other frames are returned unchanged.
QByteArray maskSecrets(QByteArray wire, bool outgoing);

// Whether `wire` is (the start of) a reply that maskSecrets knows to mask.
bool isSecretReply(const QByteArray& wire);

// Every byte but CR and LF as '*': for bytes that may hold a secret where
// no field can be found (a damaged reply to a request that carries secrets).
QByteArray maskAll(QByteArray wire);

}  // namespace cambench::comm
