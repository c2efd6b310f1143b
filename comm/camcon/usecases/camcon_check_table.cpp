// The table interface's part of the CamCon check: the first word of every
// readable run of the table map, read with one RK512 read each.
#include "camcon_check_parts.h"

#include "comm/camcon/table/table_camcon.h"
#include "comm/camcon/table/table_map.h"

#include <QCoreApplication>

namespace cambench::usecases::camcon_check {

namespace {

using comm::table::TableEntry;

// Where each entry of the map is tried: the first area of its range (the
// track areas 1..200 and the analogue areas 241..254 are alike).
struct Place {
    const TableEntry* entry;
    int area;
};

QString placeId(const Place& place) {
    return QStringLiteral("table.%1.%2").arg(place.area).arg(place.entry->firstWord);
}

QString placeReading(const Place& place) {
    QString reading =
        QCoreApplication::translate("cambench::usecases", "area %1 word %2 can be read: %3")
            .arg(place.area)
            .arg(place.entry->firstWord)
            .arg(QLatin1String(place.entry->meaning));
    if (place.entry->provisional) {
        reading += QCoreApplication::translate("cambench::usecases", " (provisional: %1)")
                       .arg(QLatin1String(place.entry->provisional));
    }
    return reading;
}

QString placeSource(const Place& place) {
    return QStringLiteral("comm/camcon/table/table_map.cpp: ") + QLatin1String(place.entry->key);
}

bool isAnalogueCamArea(int area) {
    return area >= comm::table::kFirstAnalogCamArea && area <= comm::table::kLastAnalogCamArea;
}

// Area 203 word 38 first: it says which analogue areas exist.
Result<CheckResult> analogueOutputCount(comm::table::TableCamCon& device, int& count) {
    const QString id = QStringLiteral("table.analogue_outputs");
    const QString reading = QCoreApplication::translate(
        "cambench::usecases",
        "area 203 word 38 holds the number of analogue outputs (0..14), and only their "
        "areas 241.. exist");
    const QString source = QStringLiteral("comm/camcon/table/table_camcon_extras.cpp");
    const Result<int> read = device.readAnalogueOutputCount();
    count = read ? *read : 0;
    if (read) {
        CheckResult result = held(id, reading, source);
        result.observed =
            QCoreApplication::translate("cambench::usecases", "it says %1").arg(*read);
        return result;
    }
    switch (read.error().kind) {
        case ErrorKind::Cancelled:
            return read.error();
        case ErrorKind::InvalidData:
        case ErrorKind::DeviceError:
            return refuted(id, reading, source, read.error().message);
        default:
            return couldNotTell(id, reading, source, read.error().message);
    }
}

}  // namespace

Result<QList<CheckResult>> tableAreas(comm::table::TableCamCon& device,
                                      const UseCaseProgress& progress) {
    QList<CheckResult> results;
    int analogueOutputs = 0;
    const Result<CheckResult> count = analogueOutputCount(device, analogueOutputs);
    if (!count) return count.error();
    results << *count;

    QList<Place> places;
    for (const TableEntry& entry : comm::table::tableEntries()) {
        if (comm::table::canRead(entry.access)) places << Place{&entry, entry.firstArea};
    }
    comm::table::TableLink& link = device.link();
    int silent = 0;
    for (qsizetype i = 0; i < places.size(); ++i) {
        if (progress.cancelled()) return Error::cancelled();
        const Place& place = places.at(i);
        progress.report(i, places.size(), placeId(place));
        const QString id = placeId(place);
        const QString reading = placeReading(place);
        const QString source = placeSource(place);
        if (place.entry->firstWord >= link.reachableWords()) {
            results << couldNotTell(
                id, reading, source,
                QCoreApplication::translate(
                    "cambench::usecases", "this variant of the protocol cannot address the word"));
            continue;
        }
        if (isAnalogueCamArea(place.area) && analogueOutputs == 0) {
            results << couldNotTell(
                id, reading, source,
                QCoreApplication::translate("cambench::usecases",
                                            "this device has no analogue outputs"));
            continue;
        }
        if (silent >= kSilentRequestsToGiveUp) {
            results << couldNotTell(
                id, reading, source,
                QCoreApplication::translate("cambench::usecases", "the device stopped answering"));
            continue;
        }
        const Result<QList<qint32>> words = link.readWords(place.area, place.entry->firstWord, 1);
        silent = words || words.error().kind != ErrorKind::Communication ? 0 : silent + 1;
        if (words) {
            results << held(id, reading, source);
        } else if (words.error().kind == ErrorKind::Cancelled) {
            return words.error();
        } else if (words.error().kind == ErrorKind::DeviceError) {
            results << refuted(id, reading, source, words.error().message);
        } else {
            results << couldNotTell(id, reading, source, words.error().message);
        }
    }
    return results;
}

}  // namespace cambench::usecases::camcon_check
