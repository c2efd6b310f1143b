#include "detect_device.h"

#include "comm/device/family_registry.h"
#include "comm/device/job.h"
#include "comm/transport/transport_registry.h"

#include <algorithm>

namespace cambench::usecases {

QString lineText(const comm::SerialSettings& serial) {
    return QStringLiteral("%1 baud %2%3%4")
        .arg(serial.baud)
        .arg(serial.dataBits)
        .arg(QLatin1Char(serial.parity))
        .arg(serial.stopBits);
}

namespace {

QList<const comm::ProtocolInfo*> protocolsToTry() {
    QList<const comm::ProtocolInfo*> protocols;
    for (const comm::FamilyInfo* family : comm::FamilyRegistry::instance().all()) {
        if (!family->built) continue;
        for (const comm::ProtocolInfo* protocol : comm::ProtocolRegistry::instance().all()) {
            if (protocol->familyId == family->id) protocols << protocol;
        }
    }
    // Listening first: a running token bus hears nobody else's bytes before.
    std::stable_sort(protocols.begin(), protocols.end(),
                     [](const comm::ProtocolInfo* a, const comm::ProtocolInfo* b) {
                         return a->listeningProbe && !b->listeningProbe;
                     });
    return protocols;
}

// What answers `protocol` over the open `transport`; the connection made for
// it ends here, before its transport is closed.
Result<QString> probeOnce(const comm::ProtocolInfo& protocol, comm::Transport& transport,
                          const comm::ProtocolSettings& settings) {
    Result<std::unique_ptr<comm::DeviceConnection>> device =
        protocol.connect(transport, settings, comm::lineTimingFor(protocol.defaultSerial));
    if (!device) return device.error();
    return device.value()->probe();
}

}  // namespace

QString attemptLine(const DetectAttempt& attempt) {
    const QString how = QStringLiteral("%1, %2").arg(attempt.protocolId, lineText(attempt.serial));
    if (!attempt.found.isEmpty()) return QStringLiteral("%1 (%2)").arg(attempt.found, how);
    return QStringLiteral("%1: %2").arg(how, attempt.failure);
}

Result<DetectResult> detectDevice(const QString& port, comm::JobContext& job,
                                  const DetectSettings& settingsFor) {
    DetectResult result;
    result.port = port;
    const QList<const comm::ProtocolInfo*> protocols = protocolsToTry();
    for (const comm::ProtocolInfo* protocol : protocols) {
        if (job.cancelled()) {
            result.cancelled = true;
            break;
        }
        job.progress(result.attempts.size(), protocols.size(), protocol->title);
        DetectAttempt attempt{protocol->familyId, protocol->id, protocol->defaultSerial, {}, {}};
        Result<std::unique_ptr<comm::Transport>> transport =
            comm::makeTransport({port, protocol->defaultSerial, QString()});
        if (!transport) return transport.error();
        if (const Status opened = (*transport)->open(); !opened) return opened.error();
        const comm::ProtocolSettingsPtr settings =
            settingsFor ? settingsFor(*protocol)
                        : comm::ProtocolSettingsPtr(protocol->makeSettings());
        const Result<QString> identity = probeOnce(*protocol, **transport, *settings);
        if (identity)
            attempt.found = *identity;
        else
            attempt.failure = identity.error().message;
        (*transport)->close();
        result.attempts << attempt;
        if (!attempt.found.isEmpty()) break;
    }
    job.progress(protocols.size(), protocols.size());
    return result;
}

}  // namespace cambench::usecases
