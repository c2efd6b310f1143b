// Cam tracks and programs over data areas 1..200 and area 201 words 70/71.
#include "cam_track_words.h"
#include "rk512_planner.h"
#include "table_camcon.h"
#include "table_map.h"

#include "comm/device/error_context.h"
#include "model/camcon/cam_validation.h"

#include <QCoreApplication>

namespace cambench::comm::table {

namespace {

QString trackText(int program, int output) {
    return QCoreApplication::translate("cambench::comm", "program %1, output %2")
        .arg(program)
        .arg(output);
}

bool isEmptyPlace(const QList<qint32>& words, qsizetype pair) {
    return words.at(2 * pair) == kEmptyCamWord;
}

int filledPlaces(const QList<qint32>& words) {
    int filled = 0;
    for (qsizetype pair = 0; pair < words.size() / 2; ++pair)
        filled += isEmptyPlace(words, pair) ? 0 : 1;
    return filled;
}

// Area 201 word 71 written with bit 31 deletes the program written
// (provisional reading, table_map.cpp).
constexpr quint32 kDeleteProgramBit = 0x80000000u;

}  // namespace

int TableCamCon::reachablePairs() const {
    // Place n lies at words 2n-1 and 2n.
    return qMin(kMaxTrackCams, (m_link.reachableWords() - kFirstCamWord) / 2);
}

int TableCamCon::writablePairs() const {
    const bool countReachable = m_link.reachableWords() > tableWord(u"track.cam_count");
    return countReachable ? reachablePairs() : reachablePairs() - 1;
}

Status TableCamCon::selectProgrammingProgram(int program) {
    const Status selected =
        m_link.writeWord(kStatusArea, tableWord(u"status.programming_program"), program);
    if (!selected) {
        return inContext(
            QCoreApplication::translate("cambench::comm",
                                        "selecting program %1 for programming (data area %2)")
                .arg(program)
                .arg(kStatusArea),
            selected.error());
    }
    return success();
}

Result<QList<qint32>> TableCamCon::readPairWords(int area, QStringView countKey,
                                                 const QString& what) {
    const int maxPairs = reachablePairs();
    const int countWord = tableWord(countKey);
    QList<qint32> words;
    const auto readMore = [&](int count) -> Status {
        const Result<QList<qint32>> more =
            m_link.readWords(area, kFirstCamWord + int(words.size()), count);
        if (!more) return more.error();
        words += *more;
        return success();
    };
    if (m_link.reachableWords() > countWord) {
        const Result<qint32> count = m_link.readWord(area, countWord);
        if (!count) return count.error();
        if (*count < 0 || *count > maxPairs) {
            return Error::communication(
                QCoreApplication::translate("cambench::comm",
                                            "the device reports %1 %2, which no track "
                                            "holds (0..%3); check the device")
                    .arg(*count)
                    .arg(what)
                    .arg(maxPairs));
        }
        if (*count == 0) return words;
        if (const Status read = readMore(2 * *count); !read) return read.error();
        // Places may be empty between pairs: read on until all are found.
        while (filledPlaces(words) < *count && words.size() < 2 * maxPairs) {
            const int next = qMin<int>(kMaxTableWordsPerTelegram, 2 * maxPairs - int(words.size()));
            if (const Status read = readMore(next); !read) return read.error();
        }
        if (filledPlaces(words) != *count) {
            return Error::communication(
                QCoreApplication::translate(
                    "cambench::comm",
                    "the device reports %1 %2 but its places hold %3; read again, "
                    "and check the device if this persists")
                    .arg(*count)
                    .arg(what)
                    .arg(filledPlaces(words)));
        }
        return words;
    }
    // Without the count (word 254, beyond e38's reach) read until the first
    // empty place: a track is kept packed from place 1 (provisional, README).
    while (words.size() < 2 * maxPairs) {
        const int before = int(words.size());
        const int next = qMin<int>(kMaxTableWordsPerTelegram, 2 * maxPairs - before);
        if (const Status read = readMore(next); !read) return read.error();
        if (filledPlaces(words.mid(before)) < next / 2) return words;
    }
    return Error::usage(
        QCoreApplication::translate("cambench::comm",
                                    "all %1 places that %2 reaches hold %3, so there may be "
                                    "more; read them over 3964R n96 (--protocol 3964r-n96)")
            .arg(maxPairs)
            .arg(QLatin1String(rk512VariantInfo(m_link.variant()).name), what));
}

Status TableCamCon::writePairWords(int area, const QList<qint32>& words, const QString& what,
                                   int pairs) {
    int written = 0;
    const Status done =
        m_link.writeWords(area, kFirstCamWord, words, RetryPolicy::Idempotent, &written);
    if (done) return success();
    // The first telegram replaced the whole track; later ones added places.
    const QString state =
        written == 0 ? QCoreApplication::translate(
                           "cambench::comm",
                           "the device may still hold the old %1 or already the first of the "
                           "new ones; read it to see, or write it again")
                           .arg(what)
                     : QCoreApplication::translate(
                           "cambench::comm",
                           "the device now holds only the first %1 of the %2 %3 written (the "
                           "old ones are gone); write it again")
                           .arg(qMin(written / 2, pairs))
                           .arg(pairs)
                           .arg(what);
    Error error = done.error();
    error.message = QStringLiteral("%1; %2").arg(error.message, state);
    return error;
}

Result<QList<Cam>> TableCamCon::readTrackCams(int output) {
    const Result<int> area = trackArea(output);
    if (!area) return area.error();
    const Result<QList<qint32>> words = readPairWords(
        *area, u"track.cam_count", QCoreApplication::translate("cambench::comm", "cams"));
    if (!words) return words.error();
    return camsFromTrackWords(*words);
}

Result<Track> TableCamCon::readTrack(int program, int output) {
    const QString where =
        QCoreApplication::translate("cambench::comm", "reading %1").arg(trackText(program, output));
    if (const Status selected = selectProgrammingProgram(program); !selected)
        return inContext(where, selected.error());
    Result<QList<Cam>> cams = readTrackCams(output);
    if (!cams) return inContext(where, cams.error());
    return Track{output, std::move(cams).value()};
}

Result<CamProgram> TableCamCon::readProgram(int program, int outputs, const ProgressFn& progress) {
    CamProgram result;
    result.number = program;  // no program names in the table interface
    if (const Status selected = selectProgrammingProgram(program); !selected)
        return inContext(
            QCoreApplication::translate("cambench::comm", "reading program %1").arg(program),
            selected.error());
    for (int output = 1; output <= outputs; ++output) {
        if (progress) progress(output - 1, outputs);
        Result<QList<Cam>> cams = readTrackCams(output);
        if (!cams)
            return inContext(QCoreApplication::translate("cambench::comm", "reading %1")
                                 .arg(trackText(program, output)),
                             cams.error());
        if (!cams->isEmpty()) result.tracks.insert(output, Track{output, std::move(cams).value()});
    }
    if (progress) progress(outputs, outputs);
    return result;
}

Status TableCamCon::writeTrack(int program, const Track& track) {
    const QString where = QCoreApplication::translate("cambench::comm", "writing %1")
                              .arg(trackText(program, track.output));
    const Result<int> area = trackArea(track.output);
    if (!area) return inContext(where, area.error());
    if (track.cams.size() > writablePairs() && writablePairs() < kMaxTrackCams) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "%1: %2 cams, but over %3 a track can hold at most %4 "
                                        "(the places it reaches); use 3964R n96 (--protocol "
                                        "3964r-n96)")
                .arg(where)
                .arg(track.cams.size())
                .arg(QLatin1String(rk512VariantInfo(m_link.variant()).name))
                .arg(writablePairs()));
    }
    Track sorted = track;
    normaliseTrack(sorted);
    const Result<TrackWrite> write = wholeTrackWrite(sorted.cams);
    if (!write) return inContext(where, write.error());
    if (const Status selected = selectProgrammingProgram(program); !selected)
        return inContext(where, selected.error());
    const Status written =
        writePairWords(*area, write->words, QCoreApplication::translate("cambench::comm", "cams"),
                       int(sorted.cams.size()));
    if (!written) return inContext(where, written.error());
    return success();
}

Status TableCamCon::deleteProgram(int program) {
    const Status deleted = m_link.writeWord(kStatusArea, tableWord(u"status.copy_program"),
                                            qint32(kDeleteProgramBit | quint32(program)));
    if (!deleted)
        return inContext(
            QCoreApplication::translate("cambench::comm", "deleting program %1").arg(program),
            deleted.error());
    return success();
}

Status TableCamCon::copyProgram(int from, int to) {
    const QString what =
        QCoreApplication::translate("cambench::comm", "copying program %1 to program %2")
            .arg(from)
            .arg(to);
    if (const Status selected = selectProgrammingProgram(from); !selected)
        return inContext(what, selected.error());
    const Status copied = m_link.writeWord(kStatusArea, tableWord(u"status.copy_program"), to);
    if (!copied) return inContext(what, copied.error());
    return success();
}

Status TableCamCon::copyTrack(int program, int fromOutput, int toOutput) {
    const Result<Track> source = readTrack(program, fromOutput);
    if (!source) return source.error();
    return writeTrack(program, Track{toOutput, source->cams});
}

}  // namespace cambench::comm::table
