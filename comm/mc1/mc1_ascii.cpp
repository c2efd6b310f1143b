#include "mc1_ascii.h"

#include <QRegularExpression>

namespace cambench::comm {

namespace {

constexpr char kCr = '\r';

QByteArray line(const QString& text) {
    return text.toLatin1() + kCr;
}

Error refused() {
    return Error::device(0, QStringLiteral("the controller answered ERR: it refused the request "
                                           "(a number it does not have, a value out of range, "
                                           "or an input written)"));
}

Error unexpected(const QByteArray& answer, const char* wanted) {
    return Error::communication(QStringLiteral("the answer \"%1\" is not %2")
                                    .arg(QString::fromLatin1(answer), QLatin1String(wanted)));
}

}  // namespace

QByteArray mc1AsciiReadVariable(int number) {
    return line(QStringLiteral("V%1=?").arg(number));
}

Result<QByteArray> mc1AsciiWriteVariable(int number, qint32 value) {
    if (value < kMc1Ascii24Min || value > kMc1Ascii24Max)
        return Error::usage(QStringLiteral("V%1 = %2 does not fit the MC100's 24 bits (%3..%4)")
                                .arg(number)
                                .arg(value)
                                .arg(kMc1Ascii24Min)
                                .arg(kMc1Ascii24Max));
    return line(QStringLiteral("V%1=%2").arg(number).arg(value));
}

QByteArray mc1AsciiReadPoint(const Mc1Point& point) {
    return line(QStringLiteral("%1=?").arg(mc1PointText(point)));
}

Result<QByteArray> mc1AsciiWritePoint(const Mc1Point& point, bool on) {
    if (point.area == Mc1Area::Input)
        return Error::usage(
            QStringLiteral("%1 is an input: it cannot be written").arg(mc1PointText(point)));
    return line(QStringLiteral("%1=%2").arg(mc1PointText(point)).arg(on ? 1 : 0));
}

Result<qint32> mc1AsciiValue(const QByteArray& answer) {
    if (answer.trimmed() == "ERR") return refused();
    bool ok = false;
    const qint32 value = answer.trimmed().toInt(&ok);
    if (!ok) return unexpected(answer, "a decimal value");
    return value;
}

Result<bool> mc1AsciiBit(const QByteArray& answer) {
    const QByteArray text = answer.trimmed();
    if (text == "ERR") return refused();
    if (text != "0" && text != "1") return unexpected(answer, "1 or 0");
    return text == "1";
}

Status mc1AsciiOk(const QByteArray& answer) {
    const QByteArray text = answer.trimmed();
    if (text == "ERR") return refused();
    if (text != "OK") return unexpected(answer, "OK");
    return success();
}

std::optional<Mc1AsciiRequest> parseMc1AsciiRequest(const QByteArray& text) {
    static const QRegularExpression pattern(
        QStringLiteral("^([VMAE])(\\d{1,5})=(\\?|-?\\d{1,8})$"));
    QString compact = QString::fromLatin1(text).toUpper();
    compact.remove(QLatin1Char(' '));
    const QRegularExpressionMatch match = pattern.match(compact);
    if (!match.hasMatch()) return std::nullopt;
    Mc1AsciiRequest request;
    const QChar letter = match.captured(1).at(0);
    const int number = match.captured(2).toInt();
    if (letter == QLatin1Char('V')) {
        request.target = Mc1AsciiRequest::Target::Variable;
        request.number = number;
    } else {
        request.target = Mc1AsciiRequest::Target::Point;
        const Mc1Area area = letter == QLatin1Char('M')   ? Mc1Area::Flag
                             : letter == QLatin1Char('E') ? Mc1Area::Input
                                                          : Mc1Area::Output;
        request.point = {area, number};
    }
    if (match.captured(3) != QLatin1String("?")) request.value = match.captured(3).toInt();
    return request;
}

}  // namespace cambench::comm
