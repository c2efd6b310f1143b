#pragma once

#include "compax3_object.h"

#include "model/device_identity.h"
#include "model/result.h"

#include <QDateTime>
#include <QList>
#include <QString>

namespace cambench {

// 2: each object with its name (["1902.1", "200", "Set 1 velocity"]);
// version 1 files (pairs) still load.
constexpr int kCompax3ParameterFormatVersion = 2;

// Which drive a parameter set was read from.
struct Compax3Identity {
    QString info;    // the info string (`_?`): "Compax3 S025V2 F10 I10 T40 V04.02"
    QString serial;  // object 1.4
    // The drive type the info string names ("S025V2"): a set is for
    // drives of this type; another type's set is refused unless forced.
    QString type() const;
    // What tells this drive apart from others: its serial number and type
    // ({"serial", "type"}); not known without a serial number.
    DeviceIdentity deviceIdentity() const;
};

// One object's value as the drive answered it ("12.5", "\"Axis 1\"").
struct Compax3ParameterValue {
    Compax3ObjectId id;
    QString value;
    // Its name in the dictionary the set was read with ("Set 1
    // velocity"), for a person reading the file; empty when unknown.
    // Never read back as a fact about the drive.
    QString name = {};
};

// What `c3 backup` saves: the drive's identity and a list of objects, in
// object order, each with its value.
struct Compax3ParameterSet {
    Compax3Identity drive;
    QDateTime taken;
    QString toolVersion;
    QList<Compax3ParameterValue> values;
    // Objects asked for that the drive does not have (it answered "no such
    // object"): recorded, so that a verify or restore knows they were
    // absent, not forgotten.
    QList<Compax3ObjectId> absent;
};

// {"format":"cambench-compax3-parameters","version":2,"family":"compax3",
//  "drive":{"info":…,"serial":…,"type":…},"taken":ISO UTC,"tool":…,
//  "objects":[["1901.1","100","Set 1 target"],…],"absent":["1901.0",…],"sha256":…}
// ("absent" only when the drive lacked objects): stable order (by object),
// one object a line, so that two files diff cleanly.
QByteArray compax3ParametersToJson(const Compax3ParameterSet& set);
// Checks format, version, family, hash (changed or damaged: refused),
// every object number, no object twice.
Result<Compax3ParameterSet> compax3ParametersFromJson(const QByteArray& bytes);

Status saveCompax3Parameters(const QString& path, const Compax3ParameterSet& set);
Result<Compax3ParameterSet> loadCompax3Parameters(const QString& path);

}  // namespace cambench
