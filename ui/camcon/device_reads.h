#pragma once

#include "model/result.h"

#include <QStringList>

#include <functional>

class QWidget;

namespace cambench {

class DeviceSession;
class Workspace;

// Reads from the device into the workspace. Every one of them puts what it
// read through takeIncoming(): where the values would replace unwritten
// edits, the user is asked first (also when the edits were made while the
// read was running). `context` is the parent of that question and the
// owner of the job. A Cancelled error: the user kept everything as it was.
namespace devicereads {

using Done = std::function<void(const Status&)>;

// The identity and capacities (the editors' limits follow).
quint64 readIdentity(QWidget* context, DeviceSession* session, Workspace* workspace,
                     Done done = {});
quint64 readProgram(QWidget* context, DeviceSession* session, Workspace* workspace, int program,
                    Done done = {});
quint64 readOutputSettings(QWidget* context, DeviceSession* session, Workspace* workspace,
                           Done done = {});
quint64 readSettings(QWidget* context, DeviceSession* session, Workspace* workspace,
                     Done done = {});
quint64 readUsers(QWidget* context, DeviceSession* session, Workspace* workspace, Done done = {});
quint64 readPlcNetwork(QWidget* context, DeviceSession* session, Workspace* workspace, int area,
                       int number, Done done = {});

// Identity, settings, every program, names, dead times, users and PLC
// networks (usecases::readEverything), with one progress. `skipped` says
// which parts this protocol could not read and why.
using EverythingDone = std::function<void(const Status&, const QStringList& skipped)>;
quint64 readEverything(QWidget* context, DeviceSession* session, Workspace* workspace,
                       EverythingDone done = {});

}  // namespace devicereads
}  // namespace cambench
