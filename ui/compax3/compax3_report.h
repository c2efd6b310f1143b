#pragma once

#include "comm/compax3/compax3_device.h"
#include "comm/compax3/usecases/compax3_parameters.h"
#include "model/compax3/compax3_dictionary.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QString>

#include <functional>
#include <optional>

namespace cambench {

class DeviceSession;

// What a machine's report says of a Compax3 (issue 36, item 5): read from
// the drive for the report in one job - its identity, its status and last
// error, and its parameter set (the dictionary's parameters, as a backup
// takes them) with the objects' names. A part that could not be read says
// why instead of a value.
struct Compax3ReportReading {
    QDateTime read;  // when it was read; invalid: never
    std::optional<comm::Compax3DriveStatus> status;
    QString statusNote;
    std::optional<usecases::Compax3Backup> parameters;  // with the identity
    QString parametersNote;
};

class Compax3Report {
    Q_DECLARE_TR_FUNCTIONS(cambench::Compax3Report)
public:
    // Reads it on `session`'s worker; `done` on `context`'s thread.
    static void read(DeviceSession* session, QObject* context, const Compax3Dictionary& dictionary,
                     std::function<void(Result<Compax3ReportReading>)> done);
    // The report's section (HTML): names in the language in use.
    static QString html(const std::optional<Compax3ReportReading>& reading,
                        const Compax3Dictionary& dictionary);
};

}  // namespace cambench
