#pragma once

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>

#include <limits>

namespace cambench {

// Reads typed values out of a parsed JSON file and keeps the first problem
// together with its JSON path ("programs[2].tracks[0].cams[3]: switch-off
// point is not an integer"). After the first problem every further read
// returns a default value, so a loader can read on and check failed() at
// convenient points instead of after every field.
class JsonReader {
public:
    bool failed() const { return !m_problem.isEmpty(); }
    // "<path>: <what>"; empty while nothing failed.
    const QString& problem() const { return m_problem; }
    void fail(const QString& path, const QString& what);

    // Members of `object` at `path`; `what` names the value for a person
    // ("switch-off point"). Integers must be JSON numbers without fraction.
    qint64 integer(const QJsonObject& object, const QString& path, const QString& key,
                   const QString& what, qint64 min = std::numeric_limits<qint32>::min(),
                   qint64 max = std::numeric_limits<qint32>::max());
    QString string(const QJsonObject& object, const QString& path, const QString& key,
                   const QString& what);
    bool boolean(const QJsonObject& object, const QString& path, const QString& key,
                 const QString& what);
    QJsonArray array(const QJsonObject& object, const QString& path, const QString& key);
    QJsonObject object(const QJsonObject& object, const QString& path, const QString& key);

    // A value itself, e.g. an array element, whose path is `path`.
    qint64 integerValue(const QJsonValue& value, const QString& path, const QString& what,
                        qint64 min = std::numeric_limits<qint32>::min(),
                        qint64 max = std::numeric_limits<qint32>::max());
    QJsonObject objectValue(const QJsonValue& value, const QString& path);
    QJsonArray arrayValue(const QJsonValue& value, const QString& path);

    static QString member(const QString& path, const QString& key);
    static QString element(const QString& path, int index);

private:
    bool has(const QJsonObject& object, const QString& path, const QString& key);

    QString m_problem;
};

}  // namespace cambench
