#include "table_link.h"

#include "rk512_planner.h"
#include "short_commands.h"

#include <QCoreApplication>

namespace cambench::comm::table {

namespace {

// A device whose reply block the PC answered with NAK sends it again after
// the character delay: the reply wait covers that pause, so that one
// damaged reply is not taken for a lost one (whose retry would make the
// device execute the request again).
constexpr int kDeviceRetryPauseMs = Timing3964R{}.charTimeoutMs;

QString requestLabel(const Rk512Request& request) {
    const int words = request.words16 / 2;
    // Whole phrases per order and number: a translation may need to word
    // them differently.
    const bool read = request.order == Rk512Order::Read;
    QString text;
    if (words == 1) {
        text = read ? QCoreApplication::translate("cambench::comm",
                                                  "RK512 read of area %1, offset %2 (1 word)")
                    : QCoreApplication::translate("cambench::comm",
                                                  "RK512 write of area %1, offset %2 (1 word)");
        return text.arg(request.area).arg(request.offset);
    }
    text = read ? QCoreApplication::translate("cambench::comm",
                                              "RK512 read of area %1, offset %2 (%3 words)")
                : QCoreApplication::translate("cambench::comm",
                                              "RK512 write of area %1, offset %2 (%3 words)");
    return text.arg(request.area).arg(request.offset).arg(words);
}

bool isRk512Reply(const QByteArray& reply) {
    return reply.size() >= kRk512ReplyHeaderBytes && reply.at(0) == 0 && reply.at(1) == 0 &&
           reply.at(2) == 0;
}

}  // namespace

void TableLink::setProbing() {
    m_backend.setAttempts(1);
}

TableLink::TableLink(Transport& transport, TableSettings settings, LineTiming line)
    : m_settings(settings), m_backend(settings.variant), m_engine(transport, m_backend) {
    EngineSettings engine;
    engine.line = line;
    engine.line.turnaroundMs += kDeviceRetryPauseMs;
    engine.retries = settings.retries;
    engine.fixedTimeoutMs = settings.timeoutMs;
    m_engine.setSettings(engine);
}

int TableLink::reachableWords() const {
    return rk512VariantInfo(m_settings.variant).reachableWords;
}

Result<QByteArray> TableLink::transfer(const Rk512Request& rk512, RetryPolicy retry) {
    const Result<QByteArray> telegram = encodeRk512Request(rk512);
    if (!telegram) return telegram.error();
    Request request;
    request.label = requestLabel(rk512);
    request.message = *telegram;
    request.retry = rk512.order == Rk512Order::Read ? RetryPolicy::Idempotent : retry;
    const int dataBytes = rk512.order == Rk512Order::Read ? rk512.words16 * 2 : 0;
    request.longestReplyBytes = kRk512ReplyHeaderBytes + dataBytes;
    // An error reply has no data; any other length is no answer to this
    // request (a short command's reply, a left-over reply to another read).
    request.judge = [dataBytes](const QByteArray& reply, QString& problem) {
        if (!isRk512Reply(reply)) {
            problem =
                QCoreApplication::translate("cambench::comm", "a telegram that is no RK512 reply");
            return Verdict::Ignore;
        }
        const bool error = reply.at(3) != 0;
        if (reply.size() == kRk512ReplyHeaderBytes + (error ? 0 : dataBytes))
            return Verdict::Accept;
        problem = QCoreApplication::translate("cambench::comm", "an RK512 reply of %1 bytes")
                      .arg(reply.size());
        return Verdict::Ignore;
    };
    const Result<QByteArray> reply = m_engine.send(request);
    if (!reply) return reply.error();
    return decodeRk512Reply(*reply, rk512);
}

Result<QList<qint32>> TableLink::readWords(int area, int firstWord, int count) {
    const Result<QList<Rk512Request>> requests =
        planTableRead(m_settings.variant, area, firstWord, count);
    if (!requests) return requests.error();
    QList<qint32> words;
    words.reserve(count);
    for (const Rk512Request& request : *requests) {
        const Result<QByteArray> data = transfer(request, RetryPolicy::Idempotent);
        if (!data) return data.error();
        const Result<QList<qint32>> chunk = bytesToTableWords(*data);
        if (!chunk) return chunk.error();
        words += *chunk;
    }
    return words;
}

Result<qint32> TableLink::readWord(int area, int word) {
    const Result<QList<qint32>> words = readWords(area, word, 1);
    if (!words) return words.error();
    return words->first();
}

Status TableLink::writeWords(int area, int firstWord, const QList<qint32>& values,
                             RetryPolicy retry, int* written) {
    if (written) *written = 0;
    const Result<QList<Rk512Request>> requests =
        planTableWrite(m_settings.variant, area, firstWord, values);
    if (!requests) return requests.error();
    for (const Rk512Request& request : *requests) {
        const Result<QByteArray> reply = transfer(request, retry);
        if (!reply) return reply.error();
        if (written) *written += request.words16 / 2;
    }
    return success();
}

Status TableLink::writeWord(int area, int word, qint32 value, RetryPolicy retry) {
    return writeWords(area, word, {value}, retry);
}

Result<QByteArray> TableLink::shortCommand(const QByteArray& telegram, const QString& label,
                                           int longestReplyBytes, RetryPolicy retry) {
    if (telegram.size() < 2)
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "%1: empty telegram").arg(label));
    const quint8 number = quint8(telegram.at(1));
    Request request;
    request.label = label;
    request.message = telegram;
    request.retry = retry;
    request.longestReplyBytes = longestReplyBytes;
    // The reply names the command (0x07 may come back as 0x05, notes 10),
    // or says ":Z" for an unknown one.
    request.judge = [number](const QByteArray& reply, QString& problem) {
        if (reply.size() >= 2 && reply.at(0) == kShortReplyLead) {
            const quint8 answered = quint8(reply.at(1));
            const bool typo = number == quint8(ShortCommand::WriteDeadTime) &&
                              answered == quint8(ShortCommand::WriteTracks);
            if (answered == number || answered == quint8(kShortUnknownMark) || typo)
                return Verdict::Accept;
        }
        problem = QCoreApplication::translate("cambench::comm",
                                              "a telegram that answers another command");
        return Verdict::Ignore;
    };
    return m_engine.send(request);
}

}  // namespace cambench::comm::table
