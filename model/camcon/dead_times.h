#pragma once

#include <QMap>
#include <QString>

namespace cambench {

// Dead-time compensation per output (not per program), in 0.1 ms steps.
// key = output (1-based).
using DeadTimes = QMap<int, qint32>;

// The shortest time each output must stay on for its actuator to act (a
// valve's response), in 0.1 ms steps like the dead times. Kept on the PC
// only (the project file), never on the device. key = output (1-based).
using MinimumPulses = QMap<int, qint32>;

// Output and program names (22 characters on the device including the NUL,
// so at most 21 visible characters).
struct Names {
    QMap<int, QString> outputs;   // key = output (1-based)
    QMap<int, QString> programs;  // key = program (0-based)
    friend bool operator==(const Names& a, const Names& b) {
        return a.outputs == b.outputs && a.programs == b.programs;
    }
};

}  // namespace cambench
