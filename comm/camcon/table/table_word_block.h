#pragma once

#include "table_link.h"

#include <QList>
#include <QStringView>

namespace cambench::comm::table {

// Consecutive words of one data area read in one go (as few telegrams as
// the range needs), picked by their table-map keys. Private to the
// TableCamCon files.
class WordBlock {
public:
    // Words from the first element of `firstKey` to the last of `lastKey`.
    static Result<WordBlock> read(TableLink& link, int area, QStringView firstKey,
                                  QStringView lastKey);
    static Result<WordBlock> read(TableLink& link, int area, int firstWord, int count);

    int area() const { return m_area; }
    int firstWord() const { return m_first; }
    const QList<qint32>& words() const { return m_words; }
    bool contains(int word) const { return word >= m_first && word < m_first + m_words.size(); }
    // The word at table word `word`, which the block must contain.
    qint32 word(int word) const;
    // Element `index` of the map entry `key`, which the block must contain.
    qint32 at(QStringView key, int index = 0) const;

private:
    int m_area = 0;
    int m_first = 0;
    QList<qint32> m_words;
};

}  // namespace cambench::comm::table
