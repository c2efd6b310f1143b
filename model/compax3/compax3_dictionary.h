#pragma once

#include "compax3_object.h"
#include "compax3_refusals.h"
#include "compax3_value.h"

#include "model/result.h"

#include <QHash>
#include <QList>
#include <QString>
#include <QStringList>

namespace cambench {

enum class Compax3Access {
    ReadOnly,   // "ro": read, never written (a position, the status word)
    ReadWrite,  // "rw": a parameter: read, written, saved in a parameter file
    WriteOnly,  // "wo": a function ("1904.n = $32" stores set n): written, never read
    // "cmd": read and written, never saved in a parameter file: the control
    // word, whose restore would move the axis.
    Command,
};

// An object's words for a person in one language.
struct Compax3Texts {
    QString name;
    QString group;
    QString help;
};

// What the dictionary knows of one object.
struct Compax3ObjectInfo {
    Compax3ObjectId id;
    QString name;  // "Actual position"
    Compax3Type type = Compax3Type::Integer;
    QString unit;  // "unit/s"; may be empty
    Compax3Range range;
    Compax3Access access = Compax3Access::ReadWrite;
    QString group;  // "Positioning set 1": the tree's folders
    QString help;   // a sentence for a person
    // The same words in other languages, by code ("de"); English above.
    QHash<QString, Compax3Texts> translated;

    // The name, group and help in `language` ("de"), English where the
    // dictionary has none in it.
    QString nameIn(const QString& language) const;
    QString groupIn(const QString& language) const;
    QString helpIn(const QString& language) const;

    bool readable() const { return access != Compax3Access::WriteOnly; }
    bool writable() const { return access != Compax3Access::ReadOnly; }
    // In a parameter file: what a replacement drive needs.
    bool parameter() const { return access == Compax3Access::ReadWrite; }
};

// The objects CamBench knows by name: the shipped file (the objects of
// docs/protocols/compax3.md, every meaning provisional) or a larger one the user
// loads. Objects not in it are still read and written by number.
//
// File: {"format":"cambench-compax3-dictionary","version":1,
//        "objects":[{"object":"680.5","name":"Actual position","type":"real",
//                    "unit":"unit","access":"ro","group":"Status",
//                    "min":…,"max":…,"help":"…",
//                    "de":{"name":"Istposition","group":"Status","help":"…"}}]}
class Compax3Dictionary {
public:
    // The dictionary shipped with CamBench (model/compax3/compax3-objects.json).
    static const Compax3Dictionary& builtin();
    // Refuses a broken file with the line of the problem.
    static Result<Compax3Dictionary> fromJson(const QByteArray& bytes);
    static Result<Compax3Dictionary> load(const QString& path);

    const QList<Compax3ObjectInfo>& objects() const { return m_objects; }
    const Compax3ObjectInfo* find(const Compax3ObjectId& id) const;
    // Groups in the order of the file.
    QStringList groups() const;
    // The objects a parameter file holds by default: every read-write one.
    QList<Compax3ObjectId> parameters() const;
    // What the drive's "!xxxx" answers mean: the file's "refusals", or
    // the shipped ones when the file has none.
    const Compax3RefusalTable& refusals() const { return m_refusals; }
    // Where the dictionary came from, for a person: "built in" or a path.
    const QString& source() const { return m_source; }

private:
    QList<Compax3ObjectInfo> m_objects;
    QHash<Compax3ObjectId, int> m_index;
    Compax3RefusalTable m_refusals;
    QString m_source;
};

// Why `id` is never written from a file, a compare or a restore and never
// saved in a backup (a file must never start or stop motion or trigger a
// function), or empty when it may be. Holds for the control word 1100.3 and
// the set stores 1904.n (a built-in list), for what the shipped dictionary
// marks "cmd" or "wo", and for what `inUse` marks so: a loaded dictionary
// can add to the list, never lift it.
QString compax3NeverFromAFile(const Compax3Dictionary& inUse, const Compax3ObjectId& id);
// Whether a person may not write `id` by number on the Objects page or with
// `c3 write` either: the control word, which belongs to the Motion page's
// confirmations (1100.3, and what either dictionary marks "cmd").
bool compax3IsControlWord(const Compax3Dictionary& inUse, const Compax3ObjectId& id);

// The type and range a value for `id` is checked against: the dictionary's,
// or for an unknown object a number of any size (text in quotes stays text).
Result<QString> compax3WireValueFor(const Compax3Dictionary& dictionary, const Compax3ObjectId& id,
                                    const QString& typed);

}  // namespace cambench
