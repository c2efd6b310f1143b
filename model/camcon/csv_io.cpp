#include "csv_io.h"

#include "cam_validation.h"
#include "data_validation.h"
#include "model/atomic_file.h"
#include "model/file_read.h"

#include <QCoreApplication>
#include <QSet>
#include <QStringDecoder>
#include <QStringList>

#include <limits>
#include <optional>

namespace cambench {

namespace {

const QString kCamsHeader = QStringLiteral("output,cam,on,off");
const QString kDeadTimesHeader = QStringLiteral("output,deadtime");
const QString kDeadTimeModesHeader = QStringLiteral("output,deadtime,mode,on,off");
const QString kAnalogueHeader = QStringLiteral("output,position,value");
const QString kNamesHeader = QStringLiteral("kind,number,name");
const QString kOutputKind = QStringLiteral("output");
const QString kProgramKind = QStringLiteral("program");

// One data line, split into fields, with its 1-based line number.
struct CsvRow {
    int line = 0;
    QStringList fields;
};

Error lineError(int line, const QString& reason) {
    return Error::invalidData(
        QCoreApplication::translate("cambench::model", "Line %1: %2. Nothing was imported.")
            .arg(line)
            .arg(reason));
}

// Splits one line. A field that starts with a quote runs to the next lone
// quote ("" is a literal quote); other fields are trimmed.
std::optional<QStringList> splitLine(const QString& line, QString* why) {
    QStringList fields;
    int i = 0;
    while (true) {
        QString field;
        while (i < line.size() && line.at(i).isSpace()) ++i;
        if (i < line.size() && line.at(i) == QLatin1Char('"')) {
            ++i;
            bool closed = false;
            while (i < line.size()) {
                if (line.at(i) == QLatin1Char('"')) {
                    if (i + 1 < line.size() && line.at(i + 1) == QLatin1Char('"')) {
                        field += QLatin1Char('"');
                        i += 2;
                        continue;
                    }
                    closed = true;
                    ++i;
                    break;
                }
                field += line.at(i++);
            }
            if (!closed) {
                *why = QCoreApplication::translate("cambench::model",
                                                   "a quoted field has no closing quote");
                return std::nullopt;
            }
            while (i < line.size() && line.at(i).isSpace()) ++i;
            if (i < line.size() && line.at(i) != QLatin1Char(',')) {
                *why = QCoreApplication::translate("cambench::model",
                                                   "there is text after a closing quote");
                return std::nullopt;
            }
        } else {
            const int start = i;
            while (i < line.size() && line.at(i) != QLatin1Char(',')) ++i;
            field = line.mid(start, i - start).trimmed();
        }
        fields << field;
        if (i >= line.size()) return fields;
        ++i;  // the comma
    }
}

// The data rows of `content` after checking the header and the field count.
Result<QList<CsvRow>> readRows(const QByteArray& content, const QString& header) {
    QStringDecoder decoder(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    QString text = decoder.decode(content);
    if (decoder.hasError()) {
        return Error::invalidData(QCoreApplication::translate(
            "cambench::model", "The file is not UTF-8 text. Nothing was imported."));
    }
    if (text.startsWith(QChar(0xFEFF))) text.remove(0, 1);
    const QStringList lines = text.split(QLatin1Char('\n'));
    const QString first = lines.value(0).trimmed();
    if (first != header) {
        return lineError(1, QCoreApplication::translate("cambench::model",
                                                        "the header must be \"%1\", found \"%2\"")
                                .arg(header, first.left(60)));
    }
    const int columns = int(header.count(QLatin1Char(','))) + 1;
    QList<CsvRow> rows;
    for (int i = 1; i < lines.size(); ++i) {
        QString line = lines.at(i);
        if (line.endsWith(QLatin1Char('\r'))) line.chop(1);
        if (line.trimmed().isEmpty()) continue;
        QString why;
        const std::optional<QStringList> fields = splitLine(line, &why);
        if (!fields) return lineError(i + 1, why);
        if (fields->size() != columns) {
            return lineError(
                i + 1, QCoreApplication::translate("cambench::model", "%1 fields, expected %2 (%3)")
                           .arg(fields->size())
                           .arg(columns)
                           .arg(header));
        }
        rows << CsvRow{i + 1, *fields};
    }
    return rows;
}

// A whole number in [min, max], or the reason why not.
std::optional<qint64> parseInteger(const QString& field, const char* what, qint64 min, qint64 max,
                                   QString* why) {
    bool ok = false;
    const qint64 value = field.toLongLong(&ok);
    if (!ok) {
        *why = QCoreApplication::translate("cambench::model", "%1 \"%2\" is not a whole number")
                   .arg(QLatin1String(what), field);
        return std::nullopt;
    }
    if (value < min || value > max) {
        *why = QCoreApplication::translate("cambench::model", "%1 %2 is outside %3..%4")
                   .arg(QLatin1String(what))
                   .arg(value)
                   .arg(min)
                   .arg(max);
        return std::nullopt;
    }
    return value;
}

constexpr qint64 kInt32Min = std::numeric_limits<qint32>::min();
constexpr qint64 kInt32Max = std::numeric_limits<qint32>::max();

QString quoteIfNeeded(const QString& field) {
    const bool needsQuotes =
        field.contains(QLatin1Char(',')) || field.contains(QLatin1Char('"')) ||
        (!field.isEmpty() && (field.front().isSpace() || field.back().isSpace()));
    if (!needsQuotes) return field;
    QString escaped = field;
    escaped.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + escaped + QLatin1Char('"');
}

QByteArray joinLines(const QString& header, const QStringList& rows) {
    QString text = header + QLatin1Char('\n');
    for (const QString& row : rows) text += row + QLatin1Char('\n');
    return text.toUtf8();
}

// Parses the numbers of one row; after the first bad field it only
// remembers why.
class FieldReader {
public:
    explicit FieldReader(const CsvRow& row) : m_row(row) {}

    qint64 integer(int column, const char* what, qint64 min, qint64 max) {
        if (!m_why.isEmpty()) return 0;
        return parseInteger(m_row.fields.at(column), what, min, max, &m_why).value_or(0);
    }
    bool ok() const { return m_why.isEmpty(); }
    const QString& why() const { return m_why; }

private:
    const CsvRow& m_row;
    QString m_why;
};

template <class T>
Result<T> loadCsv(const QString& path, Result<T> (*fromCsv)(const QByteArray&)) {
    const Result<QByteArray> bytes = readFileBytes(path);
    if (!bytes) return bytes.error();
    Result<T> data = fromCsv(*bytes);
    if (!data) return inFile(path, data.error());
    return data;
}

}  // namespace

QByteArray camsToCsv(const Tracks& tracks) {
    QStringList rows;
    for (Track track : tracks) {
        normaliseTrack(track);
        for (int i = 0; i < track.cams.size(); ++i) {
            rows << QStringLiteral("%1,%2,%3,%4")
                        .arg(track.output)
                        .arg(i + 1)
                        .arg(track.cams.at(i).on)
                        .arg(track.cams.at(i).off);
        }
    }
    return joinLines(kCamsHeader, rows);
}

Result<Tracks> camsFromCsv(const QByteArray& content) {
    const Result<QList<CsvRow>> rows = readRows(content, kCamsHeader);
    if (!rows) return rows.error();
    // Cams by output and 1-based cam number, with the line they came from.
    QMap<int, QMap<int, QPair<Cam, int>>> cams;
    for (const CsvRow& row : *rows) {
        FieldReader r(row);
        const int output = int(r.integer(0, "output", 1, kInt32Max));
        const int cam = int(r.integer(1, "cam", 1, kInt32Max));
        const qint32 on = qint32(r.integer(2, "switch-on point", kInt32Min, kInt32Max));
        const qint32 off = qint32(r.integer(3, "switch-off point", kInt32Min, kInt32Max));
        if (!r.ok()) return lineError(row.line, r.why());
        auto& track = cams[output];
        if (track.contains(cam)) {
            return lineError(row.line,
                             QCoreApplication::translate("cambench::model",
                                                         "output %1 has a cam %2 already (line %3)")
                                 .arg(output)
                                 .arg(cam)
                                 .arg(track.value(cam).second));
        }
        track.insert(cam, {Cam{on, off}, row.line});
    }
    Tracks tracks;
    for (auto it = cams.cbegin(); it != cams.cend(); ++it) {
        Track track;
        track.output = it.key();
        int expected = 1;
        for (auto cam = it->cbegin(); cam != it->cend(); ++cam, ++expected) {
            if (cam.key() != expected) {
                return lineError(cam->second,
                                 QCoreApplication::translate("cambench::model",
                                                             "cam %1 of output %2, but cam %3 is "
                                                             "missing; number the cams of an "
                                                             "output 1, 2, 3, ...")
                                     .arg(cam.key())
                                     .arg(it.key())
                                     .arg(expected));
            }
            track.cams << cam->first;
        }
        tracks.insert(track.output, track);
    }
    return tracks;
}

QByteArray deadTimesToCsv(const DeadTimes& deadTimes) {
    QStringList rows;
    for (auto it = deadTimes.cbegin(); it != deadTimes.cend(); ++it)
        rows << QStringLiteral("%1,%2").arg(it.key()).arg(*it);
    return joinLines(kDeadTimesHeader, rows);
}

Result<DeadTimes> deadTimesFromCsv(const QByteArray& content) {
    const Result<QList<CsvRow>> rows = readRows(content, kDeadTimesHeader);
    if (!rows) return rows.error();
    DeadTimes deadTimes;
    QMap<int, int> lineOf;
    for (const CsvRow& row : *rows) {
        FieldReader r(row);
        const int output = int(r.integer(0, "output", 1, kInt32Max));
        const qint32 value = qint32(r.integer(1, "dead time", 0, kInt32Max));
        if (!r.ok()) return lineError(row.line, r.why());
        if (lineOf.contains(output)) {
            return lineError(
                row.line, QCoreApplication::translate("cambench::model",
                                                      "output %1 has a dead time already (line %2)")
                              .arg(output)
                              .arg(lineOf.value(output)));
        }
        lineOf.insert(output, row.line);
        deadTimes.insert(output, value);
    }
    return deadTimes;
}

QByteArray deadTimeModesToCsv(const DeadTimeModes& modes) {
    QStringList rows;
    for (auto it = modes.cbegin(); it != modes.cend(); ++it) {
        rows << QStringLiteral("%1,%2,%3,%4,%5")
                    .arg(it.key())
                    .arg(it->normal)
                    .arg(deadTimeModeKey(it->mode))
                    .arg(it->on)
                    .arg(it->off);
    }
    return joinLines(kDeadTimeModesHeader, rows);
}

Result<DeadTimeTable> deadTimeTableFromCsv(const QByteArray& content) {
    DeadTimeTable table;
    // The header says which form: the plain one is checked by deadTimesFromCsv.
    QString first = QString::fromUtf8(content.left(content.indexOf('\n'))).trimmed();
    if (first.startsWith(QChar(0xFEFF))) first.remove(0, 1);
    if (first != kDeadTimeModesHeader) {
        Result<DeadTimes> plain = deadTimesFromCsv(content);
        if (!plain) return plain.error();
        table.deadTimes = *plain;
        return table;
    }
    const Result<QList<CsvRow>> rows = readRows(content, kDeadTimeModesHeader);
    if (!rows) return rows.error();
    for (const CsvRow& row : *rows) {
        FieldReader r(row);
        const int output = int(r.integer(0, "output", 1, kInt32Max));
        OutputDeadTime deadTime;
        deadTime.normal = qint32(r.integer(1, "dead time", 0, kInt32Max));
        deadTime.on = qint32(r.integer(3, "switch-on dead time", 0, kInt32Max));
        deadTime.off = qint32(r.integer(4, "switch-off dead time", 0, kInt32Max));
        if (!r.ok()) return lineError(row.line, r.why());
        const std::optional<DeadTimeMode> mode = deadTimeModeFromKey(row.fields.at(2).trimmed());
        if (!mode) {
            return lineError(row.line, QCoreApplication::translate(
                                           "cambench::model",
                                           "unknown mode \"%1\"; use normal, on/off or path-time")
                                           .arg(row.fields.at(2).trimmed()));
        }
        deadTime.mode = *mode;
        if (table.modes.contains(output)) {
            return lineError(
                row.line, QCoreApplication::translate("cambench::model", "output %1 appears twice")
                              .arg(output));
        }
        table.modes.insert(output, deadTime);
    }
    return table;
}

QByteArray analogueCamsToCsv(const QList<AnalogueCamTrack>& tracks) {
    QStringList rows;
    for (const AnalogueCamTrack& track : tracks) {
        if (track.points.isEmpty()) rows << QStringLiteral("%1,,").arg(track.output);
        for (const AnaloguePoint& point : track.points)
            rows << QStringLiteral("%1,%2,%3")
                        .arg(track.output)
                        .arg(point.position)
                        .arg(point.value);
    }
    return joinLines(kAnalogueHeader, rows);
}

Result<QList<AnalogueCamTrack>> analogueCamsFromCsv(const QByteArray& content) {
    const Result<QList<CsvRow>> rows = readRows(content, kAnalogueHeader);
    if (!rows) return rows.error();
    QMap<int, AnalogueCamTrack> tracks;
    QSet<int> cleared;  // outputs with a "no points" row
    for (const CsvRow& row : *rows) {
        FieldReader r(row);
        const int output = int(r.integer(0, "analogue output", 1, kAnalogueOutputs));
        if (!r.ok()) return lineError(row.line, r.why());
        AnalogueCamTrack& track = tracks[output];
        track.output = output;
        const bool none =
            row.fields.at(1).trimmed().isEmpty() && row.fields.at(2).trimmed().isEmpty();
        if (none ? !track.points.isEmpty() : cleared.contains(output)) {
            return lineError(row.line,
                             QCoreApplication::translate(
                                 "cambench::model",
                                 "analogue output %1 has base points and a row without any; "
                                 "use \"%1,,\" only for an output without points")
                                 .arg(output));
        }
        if (none) {
            cleared.insert(output);
            continue;
        }
        AnaloguePoint point;
        point.position = qint32(r.integer(1, "position", kInt32Min, kInt32Max));
        point.value = qint32(r.integer(2, "value", kInt32Min, kInt32Max));
        if (!r.ok()) return lineError(row.line, r.why());
        track.points << point;
    }
    return QList<AnalogueCamTrack>(tracks.cbegin(), tracks.cend());
}

QByteArray namesToCsv(const Names& names) {
    QStringList rows;
    for (auto it = names.outputs.cbegin(); it != names.outputs.cend(); ++it)
        rows << QStringLiteral("%1,%2,%3").arg(kOutputKind).arg(it.key()).arg(quoteIfNeeded(*it));
    for (auto it = names.programs.cbegin(); it != names.programs.cend(); ++it)
        rows << QStringLiteral("%1,%2,%3").arg(kProgramKind).arg(it.key()).arg(quoteIfNeeded(*it));
    return joinLines(kNamesHeader, rows);
}

Result<Names> namesFromCsv(const QByteArray& content) {
    const Result<QList<CsvRow>> rows = readRows(content, kNamesHeader);
    if (!rows) return rows.error();
    Names names;
    QMap<QPair<bool, int>, int> lineOf;
    for (const CsvRow& row : *rows) {
        const QString kind = row.fields.at(0);
        const bool isOutput = kind == kOutputKind;
        if (!isOutput && kind != kProgramKind) {
            return lineError(row.line,
                             QCoreApplication::translate("cambench::model",
                                                         "kind \"%1\" is neither \"output\" nor "
                                                         "\"program\"")
                                 .arg(kind));
        }
        FieldReader r(row);
        const int number = int(isOutput ? r.integer(1, "output", 1, kInt32Max)
                                        : r.integer(1, "program", 0, kInt32Max));
        if (!r.ok()) return lineError(row.line, r.why());
        const QString name = row.fields.at(2);
        const QString problem = nameProblem(name);
        if (!problem.isEmpty())
            return lineError(
                row.line,
                QCoreApplication::translate("cambench::model", "the name %1").arg(problem));
        const QPair<bool, int> id(isOutput, number);
        if (lineOf.contains(id)) {
            return lineError(row.line, QCoreApplication::translate(
                                           "cambench::model", "%1 %2 has a name already (line %3)")
                                           .arg(kind)
                                           .arg(number)
                                           .arg(lineOf.value(id)));
        }
        lineOf.insert(id, row.line);
        (isOutput ? names.outputs : names.programs).insert(number, name);
    }
    return names;
}

Status saveCamsCsv(const QString& path, const Tracks& tracks) {
    return writeFileAtomically(path, camsToCsv(tracks));
}

Result<Tracks> loadCamsCsv(const QString& path) {
    return loadCsv(path, &camsFromCsv);
}

Status saveDeadTimesCsv(const QString& path, const DeadTimes& deadTimes) {
    return writeFileAtomically(path, deadTimesToCsv(deadTimes));
}

Result<DeadTimes> loadDeadTimesCsv(const QString& path) {
    return loadCsv(path, &deadTimesFromCsv);
}

Result<DeadTimeTable> loadDeadTimeTableCsv(const QString& path) {
    return loadCsv(path, &deadTimeTableFromCsv);
}

Result<QList<AnalogueCamTrack>> loadAnalogueCamsCsv(const QString& path) {
    return loadCsv(path, &analogueCamsFromCsv);
}

Result<Names> loadNamesCsv(const QString& path) {
    return loadCsv(path, &namesFromCsv);
}

}  // namespace cambench
