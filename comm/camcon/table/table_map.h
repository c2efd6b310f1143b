#pragma once

#include <QList>
#include <QStringView>

#include <optional>

namespace cambench::comm::table {

// The data areas of the table interface (table-interface manual 3): 255
// areas of up to 256 signed 32-bit words. This is the one description of
// what each word holds; the table-protocol client and the simulator are
// driven from it.

inline constexpr int kFirstTrackArea = 1;  // area n = cams and dead times of output n
inline constexpr int kLastTrackArea = 200;
inline constexpr int kStatusArea = 201;
inline constexpr int kIoArea = 202;
inline constexpr int kSystemArea = 203;
inline constexpr int kAnalogOutputArea = 204;
inline constexpr int kConfigArea = 205;
inline constexpr int kFirstPlcSetValueArea = 206;     // O, P, M, X
inline constexpr int kFirstPlcActualValueArea = 210;  // O, P, M, X
inline constexpr int kMultiCamArea = 214;
inline constexpr int kPlcLinkArea = 216;
inline constexpr int kFirstAnalogCamArea =
    241;  // area 240 + n = analogue cams of analogue output n
inline constexpr int kLastAnalogCamArea = 254;
// RK512 addresses words 0..255 (one offset byte); some areas list more.
inline constexpr int kWordsPerArea = 256;

enum class TableAccess { Read, Write, ReadWrite };
inline bool canRead(TableAccess access) {
    return access != TableAccess::Write;
}
inline bool canWrite(TableAccess access) {
    return access != TableAccess::Read;
}

// A run of words with one meaning in one or more areas: `count` elements,
// element i at word firstWord + i * stride. Interleaved runs (a cam's
// switch-on and switch-off points) use stride 2.
struct TableEntry {
    int firstArea;
    int lastArea;
    int firstWord;
    int count;
    int stride;
    TableAccess access;
    const char* key;          // stable name, e.g. "status.actual_value"
    const char* meaning;      // short English text; element 0 = the first of a numbered run
    const char* unit;         // unit or scale where the manual states one, else "" (UTF-8)
    const char* provisional;  // one-line reason when this entry is a guess, else nullptr

    bool inArea(int area) const { return area >= firstArea && area <= lastArea; }
    int wordOf(int index) const { return firstWord + index * stride; }
    int lastWord() const { return wordOf(count - 1); }
    // The element index at `word`, or -1.
    int indexOf(int word) const;
};

// Every entry, ordered by area, then by first word.
const QList<TableEntry>& tableEntries();
// The entry with `key`, or nullptr.
const TableEntry* findTableEntry(QStringView key);

struct TableLocation {
    const TableEntry* entry = nullptr;
    int index = 0;  // element within the entry
};
// What word `word` of `area` holds; nullopt for free, reserved or unknown words.
std::optional<TableLocation> locateTableWord(int area, int word);
// The entries of one area, ordered by first word.
QList<const TableEntry*> tableEntriesOfArea(int area);
// The word of element `index` of the entry `key`: the client names words by
// their key, so that the map stays their one description. -1 (which no
// transfer accepts) for a key or index the map does not have.
int tableWord(QStringView key, int index = 0);

// Area 203 words 2..7 mean different things for each special encoder type
// (word 1; manual 3.4.1.1 - 3.4.1.10).
struct SpecialEncoderLayout {
    int type;                   // the value of area 203 word 1
    const char* key;            // e.g. "ssi"
    const char* name;           // e.g. "SSI"
    const char* parameters[6];  // words 2..7: key of each parameter, "" when free
    const char* provisional;    // reason, or nullptr
};
const QList<SpecialEncoderLayout>& specialEncoderLayouts();
const SpecialEncoderLayout* findSpecialEncoderLayout(int type);

}  // namespace cambench::comm::table
