#include "table_word_block.h"

#include "table_map.h"

namespace cambench::comm::table {

Result<WordBlock> WordBlock::read(TableLink& link, int area, QStringView firstKey,
                                  QStringView lastKey) {
    const TableEntry* last = findTableEntry(lastKey);
    const int first = tableWord(firstKey);
    const int end = last ? last->lastWord() : -1;
    return read(link, area, first, end - first + 1);
}

Result<WordBlock> WordBlock::read(TableLink& link, int area, int firstWord, int count) {
    Result<QList<qint32>> words = link.readWords(area, firstWord, count);
    if (!words) return words.error();
    WordBlock block;
    block.m_area = area;
    block.m_first = firstWord;
    block.m_words = std::move(words).value();
    return block;
}

qint32 WordBlock::word(int word) const {
    Q_ASSERT_X(contains(word), "WordBlock::word", "word outside the block read");
    return contains(word) ? m_words.at(word - m_first) : 0;
}

qint32 WordBlock::at(QStringView key, int index) const {
    return word(tableWord(key, index));
}

}  // namespace cambench::comm::table
