#pragma once

#include "dead_times.h"
#include "device_info.h"
#include "plc_network.h"
#include "user.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace cambench {

// Names and user names: 22 bytes on the device including the NUL.
constexpr int kMaxNameLength = 21;
// User numbers: 6 bytes on the device including the NUL.
constexpr int kMaxUserNumberLength = 5;
// Highest PLC network number as agreed for CamBench (brief, simulator).
// Doubtful: the counts of manual 5.4.6 go up to 248 and the ASCII protocol
// numbers from 0, which would make 247 the highest; change it here if a
// device refuses 248.
constexpr int kMaxPlcNumber = 248;

// Each function returns an empty string / list when everything is valid,
// otherwise one complete sentence per problem naming the item.

// What is wrong with a name (output, program, user): too long, not
// Latin-1, or a control character. Empty if it is fine.
QString nameProblem(const QString& name);

// Outputs 1..deadTimeOutputs, values 0..maxDeadTime (0.1 ms).
QStringList validateDeadTimes(const DeadTimes& deadTimes, const DeviceInfo& device);
// Output names for outputs 1..outputs, program names for 0..programs-1.
QStringList validateNames(const Names& names, const DeviceInfo& device);

// Whether a user must carry a number: a project saved without user
// numbers holds users without one (they keep the device's number).
enum class UserNumbers { Required, Optional };

// One user: name, number of 1..5 printable ASCII characters other than
// "DEL" (which means "delete" to the device), at most 256 access entries.
// Never quotes the number: it is the user's access code.
QString userProblem(const User& user, UserNumbers numbers = UserNumbers::Required);
// Every user, and that no two users share a number.
QStringList validateUsers(const QList<User>& users, UserNumbers numbers = UserNumbers::Required);

// Area O, P, M or X and a number 0..kMaxPlcNumber.
QStringList validatePlcNetwork(const PlcNetwork& network);

}  // namespace cambench
