#include "mc1_link.h"

namespace cambench::comm {

EngineSettings mc1EngineSettings(LineTiming line, int retries, int timeoutMs) {
    line.turnaroundMs = std::max(line.turnaroundMs, 500);
    return EngineSettings{line, retries, timeoutMs};
}

bool isMc1Refusal(const Error& error) {
    return error.kind == ErrorKind::DeviceError && error.deviceCode == kMc1Nak;
}

Result<QByteArray> Mc1Link::exchange(Mc1Op op, const QByteArray& parameters, int maxAttempts) {
    const Mc1Telegram* telegram = mc1Find(m_variant, op);
    if (!telegram)
        return Error::unsupported(QStringLiteral("the %1 does not know this telegram; check the "
                                                 "controller's variant")
                                      .arg(mc1VariantName(m_variant)));
    const Result<QByteArray> message = mc1Request(*telegram, parameters);
    if (!message) return message.error();
    const quint8 command = parameters.size() > 1 ? quint8(parameters.at(1)) : 0;
    Mc1Retry retry = telegram->retry;
    if (op == Mc1Op::AxisCommand || op == Mc1Op::AxisDataCommand) retry = mc1AxisRetry(op, command);
    Request request;
    request.label = QString::fromLatin1(telegram->name);
    request.message = *message;
    request.longestReplyBytes = mc1ExpectedAnswer(*telegram, parameters).length;
    request.retry = retry == Mc1Retry::Never ? RetryPolicy::Never : RetryPolicy::Idempotent;
    request.maxAttempts = maxAttempts;
    request.motion = mc1MayMove(op, command);
    const Result<QByteArray> answer = m_engine.send(request);
    if (!answer) return answer.error();
    if (answer->size() == 1 && quint8(answer->at(0)) == kMc1Nak)
        return Error::device(kMc1Nak, QStringLiteral("the %1 refused %2 (NAK): a telegram its "
                                                     "variant does not know, or parameters out "
                                                     "of range")
                                          .arg(mc1VariantName(m_variant), request.label));
    if (answer->size() == 1 && quint8(answer->at(0)) == kMc1Ack) return QByteArray();
    return answer->mid(2);
}

}  // namespace cambench::comm
