#pragma once

#include "comm/mc1/mc1_device.h"
#include "comm/mc1/mc1_parameters.h"
#include "model/mc1/mc1_backup_file.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QList>
#include <QString>

#include <optional>

namespace cambench {

class DeviceSession;

// What a machine's report says of an MC100/MC200 (issue 36, item 5): read
// from the controller for the report, all of it, in one job - its
// identity, the PLC program's state, the axes through the parameter table
// in use, every variable and the external flags. A part that could not be
// read says why instead of a value.
struct Mc1ReportReading {
    QDateTime read;      // when it was read; invalid: never
    QString controller;  // "MC200 V2 (probed)"
    std::optional<comm::Mc1ProgramStatus> program;
    QString programNote;  // why there is no program state
    QList<comm::Mc1AxisState> axes;
    QString axesNote;  // how the axes are known, or why none were read
    comm::Mc1AxisParameterTable parameters;
    std::optional<Mc1Backup> values;  // variables and flags, with the identity
    QString valuesNote;
};

class Mc1Report {
    Q_DECLARE_TR_FUNCTIONS(cambench::Mc1Report)
public:
    // Reads it on `session`'s worker; `done` on `context`'s thread.
    static void read(DeviceSession* session, QObject* context,
                     std::function<void(Result<Mc1ReportReading>)> done);
    // The report's section (HTML), every time in the report's one format.
    static QString html(const std::optional<Mc1ReportReading>& reading);
};

}  // namespace cambench
