#pragma once

#include <QString>

#include <optional>

namespace cambench {

// The 16-bit symbol words of a PLC network. Their encoding is in the PLC
// module manual, which we do not have (notes 5). Provisional reading, kept
// here and nowhere else: high byte = operand kind, low byte = number
// (0-based, shown from 1 like the device's menus), 0x0000 = empty. Only the
// kinds the notes name (the areas O, P, M, X) are decoded; every other word
// is shown and edited as raw hex.
namespace plcsymbol {

// Area letter of a kind byte (0x08 O, 0x09 P, 0x0A M, 0x0B X), or 0.
char areaLetter(int kind);
int areaKind(char letter);  // 0 when unknown

// "" for empty, "M 11" when decodable, "0x1234" otherwise.
QString display(quint16 word);
// The editable text: 4 hex digits.
QString editText(quint16 word);
// Accepts "", "-", 4 hex digits ("0A0A", "0x0A0A") or a decoded form
// ("M11", "m 11"); nullopt when the text is none of these.
std::optional<quint16> parse(const QString& text);
// Why `text` is not accepted by parse(), as a sentence for the user.
QString whyNot(const QString& text);

}  // namespace plcsymbol
}  // namespace cambench
