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

Reading placeReading(const Place& place) {
    QString text =
        QCoreApplication::translate("cambench::usecases", "area %1 word %2 can be read: %3")
            .arg(place.area)
            .arg(place.entry->firstWord)
            .arg(QLatin1String(place.entry->meaning));
    if (place.entry->provisional) {
        text += QCoreApplication::translate("cambench::usecases", " (provisional: %1)")
                    .arg(QLatin1String(place.entry->provisional));
    }
    return {QStringLiteral("table.%1.%2").arg(place.area).arg(place.entry->firstWord), text,
            QStringLiteral("comm/camcon/table/table_map.cpp: ") + QLatin1String(place.entry->key)};
}

bool isAnalogueCamArea(int area) {
    return area >= comm::table::kFirstAnalogCamArea && area <= comm::table::kLastAnalogCamArea;
}

// Area 203 word 38 first: it says which analogue areas exist.
Result<CheckResult> analogueOutputCount(comm::table::TableCamCon& device, int& count) {
    const Reading reading{
        QStringLiteral("table.analogue_outputs"),
        QCoreApplication::translate("cambench::usecases",
                                    "area 203 word 38 holds the number of analogue outputs "
                                    "(0..14), and only their areas 241.. exist"),
        QStringLiteral("comm/camcon/table/table_camcon_extras.cpp")};
    const Result<int> read = device.readAnalogueOutputCount();
    count = read ? *read : 0;
    if (read)
        return reading.held(
            QCoreApplication::translate("cambench::usecases", "it says %1").arg(*read));
    if (read.error().kind == ErrorKind::Cancelled) return read.error();
    return reading.failed(read.error());
}

// What reading the first word of `place` showed; only a cancel fails.
Result<CheckResult> readPlace(comm::table::TableLink& link, const Place& place, int analogueOutputs,
                              SilentLine& line) {
    const Reading reading = placeReading(place);
    if (place.entry->firstWord >= link.reachableWords()) {
        return reading.couldNotTell(QCoreApplication::translate(
            "cambench::usecases", "this variant of the protocol cannot address the word"));
    }
    if (isAnalogueCamArea(place.area) && analogueOutputs == 0) {
        return reading.couldNotTell(QCoreApplication::translate(
            "cambench::usecases", "this device has no analogue outputs"));
    }
    if (const std::optional<CheckResult> skipped = line.skip(reading)) return *skipped;
    const Result<QList<qint32>> words = link.readWords(place.area, place.entry->firstWord, 1);
    line.answered(words || words.error().kind != ErrorKind::Communication);
    if (words) return reading.held();
    if (words.error().kind == ErrorKind::Cancelled) return words.error();
    return reading.failed(words.error());
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
    SilentLine line;
    for (qsizetype i = 0; i < places.size(); ++i) {
        if (progress.cancelled()) return Error::cancelled();
        progress.report(i, places.size(), QLatin1String(places.at(i).entry->key));
        const Result<CheckResult> result =
            readPlace(device.link(), places.at(i), analogueOutputs, line);
        if (!result) return result.error();
        results << *result;
    }
    return results;
}

}  // namespace cambench::usecases::camcon_check
