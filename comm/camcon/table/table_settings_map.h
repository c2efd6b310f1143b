#pragma once

#include <QList>
#include <QStringView>

#include <optional>

namespace cambench::comm::table {

// Where a model setting (model/camcon/system_settings.h) lives in the data
// areas of the table interface, one line per key (table_settings_map.cpp).
// Keys without a line (texts, formats, language, terminal mode) have no
// data word: readSettings() lists them as skipped.
struct TableSetting {
    const char* key;  // model key, e.g. "axisType"
    int area;         // 201, 203 or 205
    int word;
    bool writable;
    // The model value of a device word, nullopt when the model cannot show
    // it; and the word for a model value. Both nullptr: the same number.
    std::optional<qint64> (*fromWord)(qint32 word);
    qint32 (*toWord)(qint64 value);
};
const QList<TableSetting>& tableSettings();
const TableSetting* findTableSetting(QStringView key);

// The model value of `word` under `setting`.
std::optional<qint64> settingFromWord(const TableSetting& setting, qint32 word);
qint32 settingToWord(const TableSetting& setting, qint64 value);

// The programmable special encoder (area 203 words 0..7, written as one
// block): word 0 = -1 selects it, word 1 its type, words 2..7 the
// parameters, whose meaning depends on the type (specialEncoderLayouts()).
inline constexpr int kSpecialEncoderFirstWord = 0;
inline constexpr int kSpecialEncoderWords = 8;
inline constexpr int kSpecialEncoderParameters = 6;
inline constexpr qint32 kSpecialEncoderSelected = -1;  // word 0
inline constexpr const char* kSpecialEncoderTypeKey = "specialEncoder.type";

// The model key of parameter `index` (0..5, word 2 + index) of special
// encoder `type`, or nullptr when the model has none for it.
const char* specialEncoderParameterKey(int type, int index);
// The type and parameter index of a model key "specialEncoder.<type>.<name>".
struct SpecialEncoderParameter {
    int type;
    int index;
};
std::optional<SpecialEncoderParameter> findSpecialEncoderParameter(QStringView key);

}  // namespace cambench::comm::table
