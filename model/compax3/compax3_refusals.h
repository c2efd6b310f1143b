#pragma once

#include <QList>
#include <QString>

namespace cambench {

// What a Compax3's "!xxxx" answer means, as data: the "refusals" of the
// shipped dictionary file (model/compax3/compax3-objects.json), provisional
// readings (comm/compax3/README.md C5) kept beside the objects they concern.
struct Compax3RefusalMeaning {
    int code = 0;     // the four hex digits after '!'
    QString meaning;  // "no such object"
    QString german;   // "Objekt nicht vorhanden"; empty: the English one
    // The drive does not have the object: a backup records it absent.
    bool absent = false;
};

using Compax3RefusalTable = QList<Compax3RefusalMeaning>;

// The "refusals" of a dictionary file's JSON (empty when it has none);
// entries whose code is no hex number are left out.
Compax3RefusalTable compax3RefusalsFromJson(const QByteArray& json);
// The shipped table, read once from the built-in dictionary file.
const Compax3RefusalTable& compax3Refusals();
// The meaning of `code` in the UI's language (German when the German
// translation is installed), empty for a number the table does not hold.
// Without a table: the shipped one.
QString compax3RefusalMeaning(int code);
QString compax3RefusalMeaning(const Compax3RefusalTable& table, int code);
// Whether `code` says the drive does not have the object.
bool compax3RefusalSaysAbsent(int code);
bool compax3RefusalSaysAbsent(const Compax3RefusalTable& table, int code);

}  // namespace cambench
