#pragma once

#include <QRegularExpression>
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

// `text` with its first letter capitalised: "move axis 1 by 100" starting
// a question.
inline QString capitalised(const QString& text) {
    if (text.isEmpty()) return text;
    return text.at(0).toUpper() + text.mid(1);
}

// A message from comm/ for a person at the machine: the protocol's command
// names the CLI prints for diagnosis ("reading the identity (?EPROM)", "no
// reply from the device to ?EPROM on …") are left out; the words say it.
inline QString withoutCommandNames(const QString& text) {
    static const QRegularExpression inParentheses(QStringLiteral(R"( ?\([?!][A-Z][A-Z0-9]*\))"));
    static const QRegularExpression afterTo(QStringLiteral(R"( to [?!][A-Z][A-Z0-9]*\b)"));
    QString cleaned = text;
    cleaned.remove(inParentheses);
    cleaned.remove(afterTo);
    return cleaned;
}

}  // namespace cambench
