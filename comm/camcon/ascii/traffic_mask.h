#pragma once

#include <QByteArray>

namespace cambench::comm {

// Overwrites the user numbers (the access codes of manual 5.4.1) in the wire
// bytes of one frame, or the start of one, with '*': the number fields of
// a "!USER" request when `outgoing`, of a ":USER" reply otherwise. Field
// positions come from the command catalogue; ESC-escaped bytes are masked
// together with their ESC. Other frames are returned unchanged.
QByteArray maskSecrets(QByteArray wire, bool outgoing);

}  // namespace cambench::comm
