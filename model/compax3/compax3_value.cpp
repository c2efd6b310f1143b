#include "compax3_value.h"

#include "compax3_object.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <cmath>

namespace cambench {

QString compax3TypeKey(Compax3Type type) {
    switch (type) {
        case Compax3Type::Integer:
            return QStringLiteral("integer");
        case Compax3Type::Real:
            return QStringLiteral("real");
        case Compax3Type::Text:
            return QStringLiteral("text");
    }
    return {};
}

std::optional<Compax3Type> compax3TypeFromKey(const QString& key) {
    for (Compax3Type type : {Compax3Type::Integer, Compax3Type::Real, Compax3Type::Text})
        if (compax3TypeKey(type) == key) return type;
    return std::nullopt;
}

bool Compax3Range::contains(double value) const {
    return (!min || value >= *min) && (!max || value <= *max);
}

QString Compax3Range::text() const {
    if (min && max)
        return QCoreApplication::translate("cambench::model", "%1 to %2")
            .arg(compax3NumberText(*min), compax3NumberText(*max));
    if (min)
        return QCoreApplication::translate("cambench::model", "at least %1")
            .arg(compax3NumberText(*min));
    if (max)
        return QCoreApplication::translate("cambench::model", "at most %1")
            .arg(compax3NumberText(*max));
    return {};
}

std::optional<double> compax3Number(const QString& text) {
    const QString trimmed = text.trimmed();
    bool ok = false;
    if (trimmed.startsWith(QLatin1Char('$'))) {
        const qulonglong value = trimmed.mid(1).toULongLong(&ok, 16);
        if (ok) return double(value);
        return std::nullopt;
    }
    static const QRegularExpression decimal(QStringLiteral("^[-+]?([0-9]+\\.?[0-9]*|\\.[0-9]+)$"));
    if (!decimal.match(trimmed).hasMatch()) return std::nullopt;
    const double value = trimmed.toDouble(&ok);  // QString::toDouble: C locale
    if (!ok || !std::isfinite(value)) return std::nullopt;
    return value;
}

namespace {

Result<QString> wireElement(const QString& typed, Compax3Type type, const Compax3Range& range) {
    const QString element = typed.trimmed();
    if (type == Compax3Type::Text) {
        QString text = element;
        if (text.size() >= 2 && text.startsWith(QLatin1Char('"')) &&
            text.endsWith(QLatin1Char('"')))
            text = text.mid(1, text.size() - 2);
        if (text.contains(QLatin1Char('"')) || text.contains(QLatin1Char('\r')))
            return Error::usage(QCoreApplication::translate(
                "cambench::model", "a text for the drive cannot hold \" or a line break"));
        return QLatin1Char('"') + text + QLatin1Char('"');
    }
    static const QRegularExpression germanDecimal(QStringLiteral("^[-+]?[0-9]*,[0-9]+$"));
    if (germanDecimal.match(element).hasMatch())
        return Error::usage(
            QCoreApplication::translate(
                "cambench::model",
                "\"%1\": write the number with a decimal point (%2); the drive "
                "takes a comma for a syntax error")
                .arg(element, QString(element).replace(QLatin1Char(','), QLatin1Char('.'))));
    const std::optional<double> number = compax3Number(element);
    if (!number)
        return Error::usage(
            QCoreApplication::translate("cambench::model",
                                        "\"%1\" is not a number (decimal, or $ and hexadecimal "
                                        "digits)")
                .arg(element));
    if (type == Compax3Type::Integer && std::floor(*number) != *number)
        return Error::usage(
            QCoreApplication::translate("cambench::model", "\"%1\" is not a whole number")
                .arg(element));
    if (!range.contains(*number))
        return Error::usage(
            QCoreApplication::translate("cambench::model", "%1 is outside the object's range (%2)")
                .arg(element, range.text()));
    // Hexadecimal stays as typed (a control word reads better so);
    // decimals are written out anew, with a point.
    if (element.startsWith(QLatin1Char('$'))) return element.toUpper();
    return compax3NumberText(*number);
}

}  // namespace

Result<QString> compax3WireValue(const QString& typed, Compax3Type type,
                                 const Compax3Range& range) {
    if (typed.trimmed().isEmpty())
        return Error::usage(QCoreApplication::translate("cambench::model", "no value given"));
    QStringList elements;
    // A text may hold ";": only numbers are split into a list.
    const QStringList parts =
        type == Compax3Type::Text ? QStringList{typed} : typed.split(QLatin1Char(';'));
    for (const QString& part : parts) {
        const Result<QString> element = wireElement(part, type, range);
        if (!element) return element.error();
        elements << *element;
    }
    return elements.join(QLatin1Char(';'));
}

bool compax3SameValue(const QString& a, const QString& b) {
    const QStringList left = a.split(QLatin1Char(';'));
    const QStringList right = b.split(QLatin1Char(';'));
    if (left.size() != right.size()) return false;
    for (int i = 0; i < left.size(); ++i) {
        const std::optional<double> x = compax3Number(left.at(i));
        const std::optional<double> y = compax3Number(right.at(i));
        if (x && y) {
            if (std::abs(*x - *y) > 1e-9 * std::max(1.0, std::abs(*x))) return false;
            continue;
        }
        QString l = left.at(i).trimmed();
        QString r = right.at(i).trimmed();
        l.remove(QLatin1Char('"'));
        r.remove(QLatin1Char('"'));
        if (l != r) return false;
    }
    return true;
}

}  // namespace cambench
