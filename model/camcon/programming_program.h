#pragma once

#include "device_info.h"

#include <QString>
#include <QStringList>

namespace cambench {

// The program the table interface's cam areas 1..200 read and write (data
// area 201 words 70..73): it need not be the active program, so a program
// can be edited while another one runs the machine.
struct ProgrammingProgram {
    int program = 0;         // word 70
    int selectMode = 0;      // word 72: 0 slow, 1 direct (within one cycle), 2 at the actual value
    qint32 switchValue = 0;  // word 73: the actual value of select mode 2
    friend bool operator==(const ProgrammingProgram& a, const ProgrammingProgram& b) {
        return a.program == b.program && a.selectMode == b.selectMode &&
               a.switchValue == b.switchValue;
    }
};

// "slow", "direct", "at-value": the names files and the command line use
// for select modes 0..2 ("?" for another number).
QString programmingSelectModeKey(int selectMode);
// The select mode with this name, or -1.
int programmingSelectModeFromKey(const QString& key);

// Program 0..programs-1, mode 0..2, switch value within the position range
// (mode 2 only). One sentence per problem.
QStringList validateProgrammingProgram(const ProgrammingProgram& programming,
                                       const DeviceInfo& device);

}  // namespace cambench
