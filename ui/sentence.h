#pragma once

#include <QRegularExpression>
#include <QString>

namespace cambench {

// `text` with every sentence after its first starting with a capital:
// comm/ composes its messages from lower-case parts ("no reply. the port
// is gone"), which on the screen read as sentences. A full stop after an
// abbreviation ("e.g.", "etc.") does not end a sentence.
inline QString withSentenceCapitals(const QString& text) {
    static const QRegularExpression sentenceStart(QStringLiteral(R"((\S*)([.!?])\s+(\p{Ll}))"),
                                                  QRegularExpression::UseUnicodePropertiesOption);
    static const QRegularExpression abbreviation(
        QStringLiteral(R"(^\(?(e\.g|i\.e|etc|cf|vs|approx|Min|Max|No)$)"));
    QString result = text;
    QRegularExpressionMatchIterator it = sentenceStart.globalMatch(text);
    while (it.hasNext()) {
        const QRegularExpressionMatch match = it.next();
        if (match.captured(2) == QLatin1String(".") &&
            abbreviation.match(match.captured(1)).hasMatch())
            continue;
        result[match.capturedStart(3)] = match.captured(3).at(0).toUpper();
    }
    return result;
}

// A message as one sentence: ends with a full stop unless it already ends
// with punctuation (device and line messages come both ways), so that two
// messages in a row never run together; the sentences inside it start
// with a capital.
inline QString asSentence(const QString& text) {
    const QString trimmed = withSentenceCapitals(text.trimmed());
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
