#pragma once

#include <QByteArray>
#include <QList>
#include <QSet>

#include <optional>

namespace cambench::comm {

// Test knobs of a simulated line besides the random faults (SimFaults):
// a log of the commands the devices received, devices that never answer
// (one dead device on a Multiuser line), and a command a device refuses
// on purpose with an error number of its choosing (e.g. "EEPROM full" for
// the third !NINS) without executing it.
class SimInjections {
public:
    struct Received {
        int device;
        char kind;        // '?' or '!'
        QByteArray name;  // catalogue name, "NINS"; "(unknown)" when none matched
    };

    void setLogging(bool on) { m_logging = on; }
    const QList<Received>& received() const { return m_received; }
    void clearLog() { m_received.clear(); }
    // How many received commands were `kind` + `name` (any device).
    int count(char kind, const QByteArray& name) const;
    // How many commands ('!') any device received since the log began.
    int commands() const;

    void setDead(int device, bool dead);
    bool isDead(int device) const { return m_dead.contains(device); }

    // The device answers the (skip+1)-th next `kind` `name` request with
    // error `code` instead of executing it.
    void refuse(int device, char kind, const QByteArray& name, qint32 code, int skip = 0);

    // Used by SimLine for every request a device gets.
    void record(int device, char kind, const QByteArray& name);
    std::optional<qint32> takeRefusal(int device, char kind, const QByteArray& name);

private:
    struct Refusal {
        int device;
        char kind;
        QByteArray name;
        qint32 code;
        int skip;
    };

    bool m_logging = false;
    QList<Received> m_received;
    QSet<int> m_dead;
    QList<Refusal> m_refusals;
};

}  // namespace cambench::comm
