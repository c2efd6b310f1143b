#pragma once

#include "rk512.h"

#include "model/result.h"

#include <QList>

namespace cambench::comm::table {

// Splits a range of 32-bit table words into RK512 telegrams of at most 128
// data bytes. Callers think in table words (area, word 0..255, count); the
// variant decides what goes into the offset byte.

// 128 data bytes = 64 16-bit words = 32 table words. Being even, it never
// splits a cam's on/off pair when the range starts at a pair (word 1 of
// areas 1..200 and 241..254).
inline constexpr int kMaxTableWordsPerTelegram = kRk512MaxWords16 / 2;

// One telegram's share of a transfer, in table words.
struct TableChunk {
    int area = 1;
    int firstWord = 0;
    int wordCount = 1;
    friend bool operator==(const TableChunk& a, const TableChunk& b) {
        return a.area == b.area && a.firstWord == b.firstWord && a.wordCount == b.wordCount;
    }
};

// The chunks for `wordCount` table words from `firstWord` of `area`, in
// ascending order, each at most `maxWordsPerTelegram` words. A usage error
// when the range leaves the area or the words the variant can address.
Result<QList<TableChunk>> planTableTransfer(Rk512Variant variant, int area, int firstWord,
                                            int wordCount,
                                            int maxWordsPerTelegram = kMaxTableWordsPerTelegram);

// The request for one chunk. `values` holds exactly chunk.wordCount words.
Rk512Request readRequestFor(Rk512Variant variant, const TableChunk& chunk);
Rk512Request writeRequestFor(Rk512Variant variant, const TableChunk& chunk,
                             const QList<qint32>& values);

// Planning and building in one step.
Result<QList<Rk512Request>> planTableRead(Rk512Variant variant, int area, int firstWord,
                                          int wordCount);
Result<QList<Rk512Request>> planTableWrite(Rk512Variant variant, int area, int firstWord,
                                           const QList<qint32>& values);

}  // namespace cambench::comm::table
