#pragma once

#include <QString>

namespace cambench {

// A message as one sentence: ends with a full stop unless it already ends
// with punctuation (device and line messages come both ways), so that two
// messages in a row never run together.
inline QString asSentence(const QString& text) {
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty()) return trimmed;
    const QChar last = trimmed.back();
    if (last == QLatin1Char('.') || last == QLatin1Char('!') || last == QLatin1Char('?') ||
        last == QChar(0x2026))
        return trimmed;
    return trimmed + QLatin1Char('.');
}

}  // namespace cambench
