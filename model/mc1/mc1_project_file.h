#pragma once

#include "model/result.h"

#include <QList>
#include <QString>

#include <optional>

namespace cambench {

constexpr int kMc1ProjectFormatVersion = 1;

// One variable or flag a technician named, with its value as last read
// (none when it was never read).
struct Mc1NamedValue {
    QString point;  // "V12", "M2327", "A3", "E122"
    QString name;
    std::optional<qint64> value;
};

// What CamBench keeps on the PC about an MC100/MC200: the controller it is
// for and the variables and flags a technician watches, with their names.
struct Mc1Project {
    QString variant = QStringLiteral("auto");  // "auto" or "mc200v2" (mc1_variant.h keys)
    QList<Mc1NamedValue> variables;
    QList<Mc1NamedValue> flags;
};

// {"format":"cambench-mc1-project","version":1,"family":"mc1","variant":...,
//  "variables":[{"point":"V12","name":"Feed length","value":-5}],
//  "flags":[{"point":"M2327","name":"Knife on","value":1}]}
QByteArray mc1ProjectToJson(const Mc1Project& project);
// Checks format, version, family, the variant, every point ("V" and a
// number for variables; M, E or A and a number for flags), no point twice.
Result<Mc1Project> mc1ProjectFromJson(const QByteArray& bytes);

Status saveMc1Project(const QString& path, const Mc1Project& project);
Result<Mc1Project> loadMc1Project(const QString& path);

}  // namespace cambench
