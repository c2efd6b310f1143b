#pragma once

#include "compax3_objects.h"

#include "comm/device/device_connection.h"
#include "model/compax3/compax3_dictionary.h"
#include "model/compax3/compax3_family_id.h"
#include "model/compax3/compax3_parameter_file.h"
#include "model/result.h"

#include <QDateTime>
#include <QList>
#include <QString>

#include <memory>
#include <optional>

namespace cambench::comm {

// What the drive reports about itself and its axis, read in one go.
struct Compax3DriveStatus {
    Compax3StatusWord status;
    int lastError = 1;  // 550.1; 1 = none
    double position = 0.0;
    int lastSet = 0;
    quint16 controlWord = 0;
    bool moving() const { return !status.powerless() && !status.poweredStandstill(); }
    // "powered, standing at 12.5 (set 1 done)", "moving, now at 3.2",
    // "powerless at 0": one line for a person.
    QString summary() const;
};

// The motion of a positioning set: what the confirmation shows and what is
// written into the set before it starts (unset: as the drive holds it).
struct Compax3SetValues;

struct Compax3SetMove {
    int set = 1;  // 0 = homing
    std::optional<double> target;
    std::optional<double> velocity;
    std::optional<double> acceleration;  // 1906.n only
    std::optional<double> deceleration;  // 1907.n only
    // The set as the person saw it in the confirmation: the start reads the
    // set again first, and when the drive holds other values nothing is
    // sent (Compax3CommandResult::changedSet). Unset: not compared (the
    // CLI, where nothing was shown).
    std::shared_ptr<const Compax3SetValues> shown;
};

// A positioning set as the drive holds it (190x.n), read before a start so
// that the person sees what will run and only what they change is written.
struct Compax3SetValues {
    int set = 1;
    double target = 0.0;
    double velocity = 0.0;
    double acceleration = 0.0;
    double deceleration = 0.0;
    int mode = 1;      // 1905.n: 1 absolute, 2 relative (provisional)
    QDateTime readAt;  // when these were read from the drive
    // "absolute", "relative", "mode 7": for a person.
    QString modeText() const;
    // What differs from `now`, one item each ("target 500 → 5000"); empty
    // when the drive holds what these say.
    QStringList changesTo(const Compax3SetValues& now) const;
};

// What an acting command did. Acknowledged by the drive means done; the
// state read afterwards is separate: when that read fails the command
// stays done and `readBackFailed` says why `after` is missing.
struct Compax3CommandResult {
    std::optional<Compax3DriveStatus> after;
    QString readBackFailed;
    // Something the person should know: "already powered: nothing was sent".
    QString note;
    // Nothing was sent (a powered drive's Enable, a powerless drive's STOP,
    // a start whose set changed since it was shown).
    bool nothingSent = false;
    // A start: the drive held other values than the confirmation showed; they
    // are here, as read now, and nothing was sent.
    std::optional<Compax3SetValues> changedSet;
    // "powered, standing at 3 (last set 1)" or "the state could not be read
    // back afterwards: …": one line for a person.
    QString summary() const;
};

enum class Compax3Motion {
    Enable,   // power on and acknowledge errors (1100.3 = 0, then 1)
    Disable,  // powerless (1100.3 = 0): the axis coasts or brakes as the drive is set
    JogPlus,  // moves until Stop
    JogMinus,
    Stop,  // decelerates with the ramp, stays powered (1100.3 = 1); a powerless
           // drive: nothing sent (compax3_drive_stop.cpp)
};
// "jog the axis in + direction", for confirmations and messages.
QString compax3MotionText(Compax3Motion motion);
// "start set 1 (target 100, velocity 50)".
QString compax3SetMoveText(const Compax3SetMove& move);
// Whether it sets the axis in motion (and so wants a confirmation).
bool compax3MotionMoves(Compax3Motion motion);

// A connected Parker Compax3 servo drive (ASCII objects, RS232 or RS485).
// Reads are repeated when an answer is lost; a write whose answer is lost
// is repeated only when writing it twice does the same as once (a value);
// a command that moves the axis is sent once: when its answer is lost the
// drive's state is read back and the error says what was found.
class Compax3Device : public DeviceConnection {
public:
    QString familyId() const override { return compax3FamilyId; }

    // The info string (`_?`) and serial number (1.4).
    virtual Result<Compax3Identity> identity() = 0;
    // Serial number and type (Compax3Identity::deviceIdentity).
    Result<DeviceIdentity> readIdentity() override;
    // The value as the drive answers it ("12.5", "Compax3 …"); `hex`: asks
    // for hexadecimal ("$1A").
    virtual Result<QString> readObject(const Compax3ObjectId& id, bool hex = false) = 0;
    // `wireValue` as compax3WireValue made it. A refusal is a DeviceError
    // whose message holds the drive's "!xxxx".
    virtual Status writeObject(const Compax3ObjectId& id, const QString& wireValue) = 0;

    virtual Result<Compax3DriveStatus> status() = 0;
    // An error only when the command was not acknowledged; the state read
    // afterwards is in the result. Enable reads the status first and sends
    // nothing to a powered drive (it never drops power to acknowledge).
    virtual Result<Compax3CommandResult> motion(Compax3Motion motion) = 0;
    // The set's target, velocity, ramps and mode as the drive holds them.
    virtual Result<Compax3SetValues> readSet(int set) = 0;
    // Writes what `move` sets and the drive does not hold yet into the set
    // (each value checked before the first byte), then starts it.
    virtual Result<Compax3CommandResult> moveSet(const Compax3SetMove& move) = 0;

    // The object dictionary in use (the shipped one until the person loads
    // their own): its refusal meanings word the drive's "!xxxx" answers,
    // and `check` tries its objects.
    void setDictionary(const Compax3Dictionary& dictionary) { m_dictionary = dictionary; }
    const Compax3Dictionary& dictionary() const { return m_dictionary; }

private:
    Compax3Dictionary m_dictionary = Compax3Dictionary::builtin();
};

}  // namespace cambench::comm
