#pragma once

#include <QJsonValue>
#include <QString>
#include <QStringList>

namespace cambench {

// What differs between two versions of a file, for a person reading a
// git diff (cambench-cli diff --git): by JSON member for JSON files, by
// line for anything else. Never fails: any two texts have differences.

// One line per difference, by path: "settings.encoder.resolution: 360 → 720",
// "users[2]: only in B", "programs: only in A". Members in `skipped` (at the
// top level) are left out. A long string says where it starts to differ.
QStringList jsonDifferences(const QJsonValue& a, const QJsonValue& b,
                            const QStringList& skipped = {});

// The lines that differ, as runs: "@@ -3,2 +3,1 @@" then "-old" and "+new"
// lines; empty when the texts are equal.
QString textDifferences(const QString& a, const QString& b);

}  // namespace cambench
