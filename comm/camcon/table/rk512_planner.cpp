#include "rk512_planner.h"

#include <QCoreApplication>

namespace cambench::comm::table {

Result<QList<TableChunk>> planTableTransfer(Rk512Variant variant, int area, int firstWord,
                                            int wordCount, int maxWordsPerTelegram) {
    const Rk512VariantInfo& info = rk512VariantInfo(variant);
    if (area < 1 || area > 255) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "Table transfer: data area %1 does not exist (1..255).")
                .arg(area));
    }
    if (wordCount < 1) {
        return Error::usage(
            QCoreApplication::translate(
                "cambench::comm",
                "Table transfer of %1 words from data area %2: nothing to transfer.")
                .arg(wordCount)
                .arg(area));
    }
    if (maxWordsPerTelegram < 1 || maxWordsPerTelegram > kMaxTableWordsPerTelegram) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "Table transfer: %1 words per telegram (1..%2 allowed).")
                .arg(maxWordsPerTelegram)
                .arg(kMaxTableWordsPerTelegram));
    }
    if (firstWord < 0 || qint64(firstWord) + wordCount > info.reachableWords) {
        return Error::usage(
            QCoreApplication::translate(
                "cambench::comm",
                "Table transfer: words %1..%2 of data area %3 are outside the words "
                "0..%4 that %5 can address.%6")
                .arg(firstWord)
                .arg(qint64(firstWord) + wordCount - 1)
                .arg(area)
                .arg(info.reachableWords - 1)
                .arg(QLatin1String(info.name))
                .arg(variant == Rk512Variant::E38
                         ? QCoreApplication::translate(
                               "cambench::comm", " Switch the device to 3964R n96 to reach them.")
                         : QString()));
    }
    QList<TableChunk> chunks;
    for (int word = firstWord; word < firstWord + wordCount; word += maxWordsPerTelegram) {
        chunks.append({area, word, qMin(maxWordsPerTelegram, firstWord + wordCount - word)});
    }
    return chunks;
}

Rk512Request readRequestFor(Rk512Variant variant, const TableChunk& chunk) {
    Rk512Request request;
    request.order = Rk512Order::Read;
    request.area = chunk.area;
    request.offset = chunk.firstWord * rk512VariantInfo(variant).offsetsPerWord;
    request.words16 = chunk.wordCount * 2;
    return request;
}

Rk512Request writeRequestFor(Rk512Variant variant, const TableChunk& chunk,
                             const QList<qint32>& values) {
    Rk512Request request = readRequestFor(variant, chunk);
    request.order = Rk512Order::Write;
    request.data = tableWordsToBytes(values);
    return request;
}

Result<QList<Rk512Request>> planTableRead(Rk512Variant variant, int area, int firstWord,
                                          int wordCount) {
    const Result<QList<TableChunk>> chunks = planTableTransfer(variant, area, firstWord, wordCount);
    if (!chunks) return chunks.error();
    QList<Rk512Request> requests;
    for (const TableChunk& chunk : *chunks) requests.append(readRequestFor(variant, chunk));
    return requests;
}

Result<QList<Rk512Request>> planTableWrite(Rk512Variant variant, int area, int firstWord,
                                           const QList<qint32>& values) {
    const Result<QList<TableChunk>> chunks =
        planTableTransfer(variant, area, firstWord, int(values.size()));
    if (!chunks) return chunks.error();
    QList<Rk512Request> requests;
    for (const TableChunk& chunk : *chunks) {
        requests.append(writeRequestFor(variant, chunk,
                                        values.mid(chunk.firstWord - firstWord, chunk.wordCount)));
    }
    return requests;
}

}  // namespace cambench::comm::table
