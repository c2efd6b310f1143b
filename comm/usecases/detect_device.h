#pragma once

#include "comm/device/protocol_registry.h"
#include "comm/transport/transport.h"
#include "model/result.h"

#include <QList>
#include <QString>

#include <functional>
#include <optional>

namespace cambench::comm {
class JobContext;
}

namespace cambench::usecases {

// One try of Detect: a protocol at its default line settings.
struct DetectAttempt {
    QString familyId;
    QString protocolId;
    comm::SerialSettings serial;
    QString found;    // what answered (DeviceConnection::identify), empty when nothing did
    QString failure;  // why not, when nothing answered
};

struct DetectResult {
    QString port;
    QList<DetectAttempt> attempts;  // in the order tried; the last one found, if any did
    bool cancelled = false;

    const DetectAttempt* found() const {
        return !attempts.isEmpty() && !attempts.last().found.isEmpty() ? &attempts.last() : nullptr;
    }
};

// The protocol settings to try a protocol with (device number, PC number):
// by default its own defaults.
using DetectSettings = std::function<comm::ProtocolSettingsPtr(const comm::ProtocolInfo& protocol)>;

// What is on `port`: each built family's protocols, each at its default
// line settings, until a device identifies itself: first those whose probe
// only listens (ProtocolInfo::listeningProbe: a token bus, which the others'
// requests would disturb), then the rest in the order they were registered.
// Only identification queries are sent. Opens its own transport per try:
// the worker must not hold the port. Fails only when the port cannot be
// opened at all; a line where nothing answers is a result with every
// attempt's failure.
Result<DetectResult> detectDevice(const QString& port, comm::JobContext& job,
                                  const DetectSettings& settingsFor = {});

// "9600 baud 8N1"
QString lineText(const comm::SerialSettings& serial);

// "CamCon, EPROM …, device 0 (standard, 9600 baud 8N1)" or "nothing answered
// (tried: …)": one line for the CLI and the status bar.
QString attemptLine(const DetectAttempt& attempt);

}  // namespace cambench::usecases
