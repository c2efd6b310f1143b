#include "compax3_syntax.h"

#include "model/compax3/compax3_refusals.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace cambench::comm {

QByteArray compax3ReadCommand(const Compax3ObjectId& id, bool hexAnswer) {
    QByteArray command = "O" + QByteArray::number(id.index) + ',' + QByteArray::number(id.subindex);
    if (hexAnswer) command += '$';
    return command;
}

QByteArray compax3WriteCommand(const Compax3ObjectId& id, const QString& wireValue) {
    return compax3ReadCommand(id) + '=' + wireValue.toLatin1();
}

QByteArray compax3InfoCommand() {
    return QByteArrayLiteral("_?");
}

QByteArray compax3RequestLine(const QByteArray& command, int address) {
    QByteArray line;
    if (address >= 0) line += QByteArray::number(address);
    return line + command + kCompax3End;
}

Result<Compax3Reply> parseCompax3Reply(const QByteArray& raw) {
    QByteArray line = raw;
    if (line.startsWith(kCompax3Rs485Mark)) line.remove(0, 1);
    for (char c : line)
        if (quint8(c) < 0x20 || quint8(c) > 0x7E)
            return Error::invalidData(
                QCoreApplication::translate("cambench::comm",
                                            "the answer \"%1\" holds a byte that is no printable "
                                            "ASCII (0x%2)")
                    .arg(QString::fromLatin1(line.toPercentEncoding(" !\"$*,.;=>_-+")))
                    .arg(quint8(c), 2, 16, QLatin1Char('0')));
    Compax3Reply reply;
    if (line == ">") {
        reply.kind = Compax3Reply::Ok;
        return reply;
    }
    if (line.startsWith('!')) {
        static const QRegularExpression code(QStringLiteral("^![0-9A-Fa-f]{4}$"));
        const QString text = QString::fromLatin1(line);
        if (!code.match(text).hasMatch())
            return Error::invalidData(
                QCoreApplication::translate("cambench::comm",
                                            "the answer \"%1\" is no error number (! and four hex "
                                            "digits)")
                    .arg(text));
        reply.kind = Compax3Reply::Error;
        reply.code = text.mid(1).toInt(nullptr, 16);
        return reply;
    }
    if (line.isEmpty())
        return Error::invalidData(
            QCoreApplication::translate("cambench::comm", "the answer is an empty line"));
    reply.text = QString::fromLatin1(line);
    return reply;
}

bool compax3RefusalMeansAbsent(const cambench::Error& error) {
    return compax3RefusalMeansAbsent(error, compax3Refusals());
}

bool compax3RefusalMeansAbsent(const cambench::Error& error,
                               const cambench::Compax3RefusalTable& table) {
    return error.kind == ErrorKind::DeviceError &&
           compax3RefusalSaysAbsent(table, error.deviceCode);
}

cambench::Error compax3RefusalError(const QByteArray& command, int code) {
    return compax3RefusalError(command, code, compax3Refusals());
}

cambench::Error compax3RefusalError(const QByteArray& command, int code,
                                    const cambench::Compax3RefusalTable& table) {
    const QString number = QStringLiteral("!%1").arg(code, 4, 16, QLatin1Char('0')).toUpper();
    const QString meaning = compax3RefusalMeaning(table, code);
    const QString text =
        meaning.isEmpty()
            ? QCoreApplication::translate("cambench::comm",
                                          "the drive refused %1 with %2 (an error number "
                                          "CamBench does not know: see the drive's manual)")
                  .arg(QString::fromLatin1(command), number)
            : QCoreApplication::translate("cambench::comm", "the drive refused %1 with %2 (%3)")
                  .arg(QString::fromLatin1(command), number, meaning);
    return cambench::Error::device(code, text);
}

QByteArray compax3Canonical(const QByteArray& command) {
    QByteArray out;
    bool quoted = false;
    for (char c : command) {
        if (c == '"') quoted = !quoted;
        if (!quoted && c == ' ') continue;
        out += quoted ? c : char(QChar::toUpper(uchar(c)));
    }
    return out;
}

std::optional<Compax3Request> parseCompax3Request(const QByteArray& canonical) {
    if (canonical == "_?") return Compax3Request{Compax3Request::Info, {}, false, {}};
    if (!canonical.startsWith('O')) return std::nullopt;
    QString text = QString::fromLatin1(canonical);
    Compax3Request request;
    if (const qsizetype equals = text.indexOf(QLatin1Char('=')); equals >= 0) {
        request.kind = Compax3Request::Write;
        request.value = text.mid(equals + 1);
        text.truncate(equals);
    }
    // A '$' after the subindex asks for a hexadecimal answer (reads only).
    if (text.endsWith(QLatin1Char('$'))) {
        if (request.kind == Compax3Request::Write) return std::nullopt;
        request.hexAnswer = true;
        text.chop(1);
    }
    const Result<Compax3ObjectId> id = parseCompax3Object(text);
    if (!id) return std::nullopt;
    request.id = *id;
    return request;
}

}  // namespace cambench::comm
