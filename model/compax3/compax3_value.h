#pragma once

#include "model/result.h"

#include <QString>

#include <optional>

namespace cambench {

// What an object holds, as the dictionary says.
enum class Compax3Type {
    Integer,  // whole numbers; $ hexadecimal accepted
    Real,     // decimal numbers with a decimal point
    Text,     // sent in "…"
};

// "integer", "real", "text": the dictionary file's words.
QString compax3TypeKey(Compax3Type type);
std::optional<Compax3Type> compax3TypeFromKey(const QString& key);

// The limits a value must keep (a dictionary's min/max; unset: any).
struct Compax3Range {
    std::optional<double> min;
    std::optional<double> max;
    bool contains(double value) const;
    // "0 to 65535", "at least 0", "": for messages.
    QString text() const;
};

// A value typed by a person or read from a file, checked and made into what
// goes after "=" on the wire: numbers with a decimal point ("12.5", "$1F"),
// text in quotes, lists joined by ";". A German "12,5" is refused with a
// message asking for the point; a number outside `range` says the range.
Result<QString> compax3WireValue(const QString& typed, Compax3Type type,
                                 const Compax3Range& range = {});

// The number a drive's answer or a typed value stands for ("12.5", "$1F",
// "-3"); nullopt for text and lists.
std::optional<double> compax3Number(const QString& text);

// Whether two values mean the same: numbers compared as numbers ("12.50"
// and "12.5", "$10" and "16"), anything else as text without quotes.
bool compax3SameValue(const QString& a, const QString& b);

}  // namespace cambench
