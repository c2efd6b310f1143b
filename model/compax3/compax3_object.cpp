#include "compax3_object.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace cambench {

QString Compax3ObjectId::text() const {
    return QStringLiteral("%1.%2").arg(index).arg(subindex);
}

namespace {

// A decimal number, or $ and hexadecimal digits.
std::optional<int> numberPart(const QString& text) {
    bool ok = false;
    const int value =
        text.startsWith(QLatin1Char('$')) ? text.mid(1).toInt(&ok, 16) : text.toInt(&ok, 10);
    if (!ok) return std::nullopt;
    return value;
}

}  // namespace

Result<Compax3ObjectId> parseCompax3Object(const QString& text) {
    QString compact = text;
    compact.remove(QLatin1Char(' '));
    compact = compact.toUpper();
    if (compact.startsWith(QLatin1Char('O'))) compact.remove(0, 1);
    static const QRegularExpression pattern(
        QStringLiteral("^(\\$[0-9A-F]+|[0-9]+)[.,](\\$[0-9A-F]+|[0-9]+)$"));
    const QRegularExpressionMatch match = pattern.match(compact);
    const std::optional<int> index =
        match.hasMatch() ? numberPart(match.captured(1)) : std::nullopt;
    const std::optional<int> subindex =
        match.hasMatch() ? numberPart(match.captured(2)) : std::nullopt;
    if (!index || !subindex || *index > 0xFFFF || *subindex > 0xFF)
        return Error::usage(QCoreApplication::translate(
                                "cambench::model",
                                "\"%1\" is not a Compax3 object; write index.subindex, e.g. 680.5 "
                                "(also o680.5, O 680,5, $ for hexadecimal; index up to 65535, "
                                "subindex up to 255)")
                                .arg(text));
    return Compax3ObjectId{*index, *subindex};
}

QString compax3HexText(qint64 value, int digits) {
    return QLatin1Char('$') +
           QString::number(value, 16).toUpper().rightJustified(digits, QLatin1Char('0'));
}

QString compax3NumberText(double value) {
    // QString::number ignores the locale: always a '.'.
    QString text = QString::number(value, 'f', 6);
    if (text.contains(QLatin1Char('.'))) {
        while (text.endsWith(QLatin1Char('0'))) text.chop(1);
        if (text.endsWith(QLatin1Char('.'))) text.chop(1);
    }
    if (text == QLatin1String("-0")) text = QStringLiteral("0");
    return text;
}

}  // namespace cambench
