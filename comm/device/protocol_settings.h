#pragma once

#include <QString>
#include <QStringList>
#include <QVariantMap>

#include <memory>

namespace cambench::comm {

// The connection settings one protocol brings, beside the line's (port,
// baud, parity): a CamCon ASCII link has its framing, device and PC number,
// a table-interface link its 3964R variant, a Compax3 its drive address.
// Each protocol subclasses this (as QGroundControl's LinkConfiguration
// subclasses do) and brings a settings widget of its own in ui/.
class ProtocolSettings {
public:
    virtual ~ProtocolSettings() = default;

    // The registry id: "standard", "multiuser", "3964r-n96", ...
    virtual QString protocolId() const = 0;
    virtual std::unique_ptr<ProtocolSettings> clone() const = 0;

    // The device addressed on a bus (0..63), or -1 on a point-to-point link.
    virtual int device() const { return -1; }
    virtual void setDevice(int device) { Q_UNUSED(device); }
    // The user's fixed per-attempt timeout; 0 = derived from the line.
    virtual int timeoutMs() const { return 0; }

    // For QSettings and logs: only plain values.
    virtual QVariantMap toMap() const = 0;
    virtual void fromMap(const QVariantMap& map) = 0;
};

using ProtocolSettingsPtr = std::shared_ptr<const ProtocolSettings>;

}  // namespace cambench::comm
