#pragma once

#include "stop_control.h"
#include "stop_round.h"

#include <QList>
#include <QPointer>

namespace cambench {

// The STOP of the whole program: every window's STOP (the single device's
// MotionStop, each machine's MachineStop) at once. Escape reaches it from
// every window, dialog, open menu and cell editor of the program
// (StopShortcut), and every dialog shows its button (DialogStop): a modal
// dialog blocks every other window, so from inside it this is the only
// STOP a person can reach, and it must reach whatever moves. A STOP changes
// nothing but motion: stopping a device of another window too is safe.
//
// Made on first use and kept for the application's life; a new window or
// dialog gets all of it without doing anything but add() its STOP.
class ProgramStop : public StopControl {
    Q_OBJECT
public:
    static ProgramStop& instance();

    // A window's STOP joins the program's (again: nothing happens).
    void add(StopControl* stop);

    bool available() const override;
    bool armed() const override;
    void stopAll() override;

private:
    explicit ProgramStop(QObject* parent);

    QList<QPointer<StopControl>> m_stops;
    QPointer<StopRound> m_round;
};

}  // namespace cambench
