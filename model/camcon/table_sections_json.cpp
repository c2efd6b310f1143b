#include "table_sections_json.h"

#include <QCoreApplication>
#include <QSet>

namespace cambench {

namespace {
QString key(const char* text) {
    return QString::fromLatin1(text);
}
}  // namespace

QJsonArray analogueCamsToJson(const QList<AnalogueCamTrack>& tracks) {
    QJsonArray array;
    for (const AnalogueCamTrack& track : tracks) {
        QJsonArray points;
        for (const AnaloguePoint& point : track.points)
            points.append(QJsonArray{point.position, point.value});
        array.append(QJsonObject{{key("output"), track.output}, {key("points"), points}});
    }
    return array;
}

QList<AnalogueCamTrack> analogueCamsFromJson(JsonReader& reader, const QJsonArray& array,
                                             const QString& path) {
    QList<AnalogueCamTrack> tracks;
    QSet<int> seen;
    for (int i = 0; i < array.size() && !reader.failed(); ++i) {
        const QString trackPath = JsonReader::element(path, i);
        const QJsonObject object = reader.objectValue(array.at(i), trackPath);
        AnalogueCamTrack track;
        track.output =
            int(reader.integer(object, trackPath, key("output"),
                               QCoreApplication::translate("cambench::model", "analogue output"), 1,
                               kAnalogueOutputs));
        const QString pointsPath = JsonReader::member(trackPath, key("points"));
        const QJsonArray points = reader.array(object, trackPath, key("points"));
        for (int p = 0; p < points.size() && !reader.failed(); ++p) {
            const QString pointPath = JsonReader::element(pointsPath, p);
            const QJsonArray pair = reader.arrayValue(points.at(p), pointPath);
            if (!reader.failed() && pair.size() != 2) {
                reader.fail(pointPath, QCoreApplication::translate(
                                           "cambench::model",
                                           "a base point is [position, value], two numbers"));
                break;
            }
            AnaloguePoint point;
            point.position = qint32(
                reader.integerValue(pair.at(0), JsonReader::element(pointPath, 0),
                                    QCoreApplication::translate("cambench::model", "position")));
            point.value = qint32(
                reader.integerValue(pair.at(1), JsonReader::element(pointPath, 1),
                                    QCoreApplication::translate("cambench::model", "value")));
            track.points << point;
        }
        if (!reader.failed() && seen.contains(track.output)) {
            reader.fail(
                JsonReader::member(trackPath, key("output")),
                QCoreApplication::translate("cambench::model", "analogue output %1 appears twice")
                    .arg(track.output));
        }
        seen.insert(track.output);
        tracks << track;
    }
    return tracks;
}

QJsonObject programmingProgramToJson(const ProgrammingProgram& programming) {
    return {{key("program"), programming.program},
            {key("selectMode"), programmingSelectModeKey(programming.selectMode)},
            {key("switchValue"), programming.switchValue}};
}

ProgrammingProgram programmingProgramFromJson(JsonReader& reader, const QJsonObject& object,
                                              const QString& path) {
    ProgrammingProgram programming;
    programming.program =
        int(reader.integer(object, path, key("program"),
                           QCoreApplication::translate("cambench::model", "programming program")));
    const QString mode =
        reader.string(object, path, key("selectMode"),
                      QCoreApplication::translate("cambench::model", "select mode"));
    programming.selectMode = programmingSelectModeFromKey(mode);
    if (!reader.failed() && programming.selectMode < 0) {
        reader.fail(JsonReader::member(path, key("selectMode")),
                    QCoreApplication::translate("cambench::model",
                                                "unknown select mode \"%1\"; use slow, direct or "
                                                "at-value")
                        .arg(mode));
    }
    programming.switchValue =
        qint32(reader.integer(object, path, key("switchValue"),
                              QCoreApplication::translate("cambench::model", "switch value")));
    return programming;
}

}  // namespace cambench
