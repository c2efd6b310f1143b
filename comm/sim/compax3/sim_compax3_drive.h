#pragma once

#include "comm/sim/sim_shaft.h"
#include "model/compax3/compax3_dictionary.h"

#include <QByteArray>
#include <QHash>
#include <QList>
#include <QSet>
#include <QString>

namespace cambench::comm {

// A simulated Parker Compax3 (docs/protocols/compax3.md): the shipped object
// dictionary with types, ranges and read-only objects, the status word, and
// an axis that moves when a set is started or a jog runs. Power follows the
// control word as the drive's does: only a rising edge of b0 powers the
// drive, and that edge acknowledges a pending error; b0 = 0 drops power; an
// error stops the axis, drops power and holds until acknowledged; a
// powerless drive does not move. Its answers to a
// request are the drive's: a value, '>', or '!xxxx' (the emulator's
// numbers: 0001 syntax, 0002 no such object, 0003 read-only, 0004 out of
// range, 0005 not possible now, 0006 wrong type).
class SimCompax3Drive {
public:
    explicit SimCompax3Drive(QString type = QStringLiteral("S025V2"),
                             QString serial = QStringLiteral("C3-4711-0815"));

    // One request line (without address and CR), at `nowMs`; the answer
    // without '*' and CR.
    QByteArray answer(const QByteArray& command, qint64 nowMs);

    // Tests and demos.
    QString value(const Compax3ObjectId& id) const { return m_values.value(id); }
    void setValue(const Compax3ObjectId& id, const QString& value) { m_values.insert(id, value); }
    double position() const { return m_position; }
    bool moving() const { return m_moving || m_jog != 0; }
    // How the axis moves as of the last request (a simulated machine's
    // shaft follows it between requests).
    SimShaftMotion motion() const;
    QString infoString() const;
    // A fault the drive reports in 550.1: the axis stops and power drops;
    // it holds until a rising edge of b0 acknowledges it.
    void raiseError(int code);
    bool powered() const { return m_powered; }
    int lastError() const { return m_error; }
    // A firmware without `id`: reading or writing it answers !0002.
    void removeObject(const Compax3ObjectId& id) { m_missing.insert(id); }
    // Reads of `id` answer !0005 (not possible now), writes still work: a
    // drive whose read-backs fail after a command.
    void refuseReads(const Compax3ObjectId& id) { m_unreadable.insert(id); }
    // Every request the drive answered, as it read it (upper case, no
    // spaces): tests count what was sent.
    const QList<QByteArray>& requests() const { return m_requests; }

private:
    QByteArray read(const Compax3ObjectId& id, bool hex) const;
    QByteArray write(const Compax3ObjectId& id, const QString& value);
    QByteArray control(quint16 word);
    void advance(qint64 nowMs);
    quint16 statusWord() const;
    double setValue(int object, int set) const;

    QString m_type;
    QString m_serial;
    QHash<Compax3ObjectId, QString> m_values;  // the parameters (190x.n, ...)
    QSet<Compax3ObjectId> m_missing;
    QSet<Compax3ObjectId> m_unreadable;
    QList<QByteArray> m_requests;
    quint16 m_control = 0;
    // Powered: set only by a rising edge of b0, cleared by b0 = 0 or an error.
    bool m_powered = false;
    int m_error = 1;
    int m_lastSet = 0;
    bool m_zeroKnown = false;
    double m_position = 0.0;
    double m_target = 0.0;
    double m_velocity = 0.0;
    bool m_moving = false;
    int m_movingSet = 0;
    int m_jog = 0;  // +1, -1 or 0
    qint64 m_lastMs = -1;
};

}  // namespace cambench::comm
