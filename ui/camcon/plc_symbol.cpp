#include "plc_symbol.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace cambench::plcsymbol {

namespace {
constexpr char kLetters[] = {'O', 'P', 'M', 'X'};
constexpr int kFirstKind = 0x08;
}  // namespace

char areaLetter(int kind) {
    const int index = kind - kFirstKind;
    return index >= 0 && index < 4 ? kLetters[index] : 0;
}

int areaKind(char letter) {
    for (int i = 0; i < 4; ++i) {
        if (kLetters[i] == letter) return kFirstKind + i;
    }
    return 0;
}

QString display(quint16 word) {
    if (word == 0) return {};
    const char letter = areaLetter(word >> 8);
    if (letter) return QStringLiteral("%1 %2").arg(QLatin1Char(letter)).arg((word & 0xFF) + 1);
    return QStringLiteral("0x%1")
        .arg(word, 4, 16, QLatin1Char('0'))
        .toUpper()
        .replace(QLatin1String("0X"), QLatin1String("0x"));
}

QString editText(quint16 word) {
    return QStringLiteral("%1").arg(word, 4, 16, QLatin1Char('0')).toUpper();
}

std::optional<quint16> parse(const QString& input) {
    const QString text = input.trimmed();
    if (text.isEmpty() || text == QLatin1String("-")) return quint16(0);
    static const QRegularExpression hex(QStringLiteral("^(?:0[xX])?([0-9A-Fa-f]{4})$"));
    if (const auto m = hex.match(text); m.hasMatch())
        return quint16(m.captured(1).toUInt(nullptr, 16));
    static const QRegularExpression decoded(QStringLiteral("^([OPMXopmx])\\s*(\\d{1,3})$"));
    if (const auto m = decoded.match(text); m.hasMatch()) {
        const int kind = areaKind(m.captured(1).toUpper().at(0).toLatin1());
        const int number = m.captured(2).toInt();
        if (number >= 1 && number <= 256) return quint16((kind << 8) | (number - 1));
    }
    return std::nullopt;
}

QString whyNot(const QString& input) {
    const QString text = input.trimmed();
    static const QRegularExpression operand(QStringLiteral("^([A-Za-z])\\s*(\\d+)$"));
    const auto m = operand.match(text);
    if (m.hasMatch() && !areaKind(m.captured(1).toUpper().at(0).toLatin1())) {
        // I and E (inputs in English and German) are the usual slips.
        return QCoreApplication::translate(
                   "cambench::plcsymbol",
                   "\"%1\" is not taken: CamBench knows the operands O, P, M and X "
                   "only (P are the cam controller's inputs, e.g. P5). Enter one of "
                   "them with a number, or the symbol word as 4 hex digits.")
            .arg(text);
    }
    if (m.hasMatch())
        return QCoreApplication::translate("cambench::plcsymbol",
                                           "\"%1\" is not taken: the number must be 1 … 256.")
            .arg(text);
    return QCoreApplication::translate(
               "cambench::plcsymbol",
               "\"%1\" is not taken: enter an operand such as M11 or P5, 4 hex "
               "digits (0A0A), or nothing to clear the symbol.")
        .arg(text);
}

}  // namespace cambench::plcsymbol
