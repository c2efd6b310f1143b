#pragma once

// `check` (issue 29): each provisional reading of ours about a device
// family - a command's reply format, a table's area, an addressing rule -
// tried on the connected device by reading only, with one verdict each.
// The frame knows no family: a family registers its FamilyCheck (what its
// requests that only read look like, and its checks) in its own folder;
// checkDevice() runs the one of the connection's family behind a gate on
// the engine that keeps every other request off the line.

#include "use_case_progress.h"

#include "comm/device/device_connection.h"
#include "comm/engine/request.h"
#include "model/result.h"

#include <QJsonObject>
#include <QList>
#include <QString>

#include <functional>

namespace cambench::usecases {

enum class CheckVerdict {
    Held,          // the device answered as we read the manual
    Refuted,       // it answered otherwise: `observed` says what
    CouldNotTell,  // no answer that decides it: `observed` says why
};

// "held", "refuted", "could not tell" (also the JSON values).
QString checkVerdictText(CheckVerdict verdict);

// One reading and what the device said to it.
struct CheckResult {
    QString id;       // stable, for the report sent back: "ascii.?NF", "table.area.203.38"
    QString reading;  // what we believe, for a person
    QString source;   // where that belief is written, the one place to correct
    CheckVerdict verdict = CheckVerdict::CouldNotTell;
    QString observed;  // refuted: what the device answered instead; could not tell: why
};

// What one check tries, and its verdict in one call.
struct Reading {
    QString id;      // CheckResult::id
    QString text;    // CheckResult::reading
    QString source;  // CheckResult::source

    CheckResult held(QString observed = {}) const;
    CheckResult refuted(QString observed) const;
    CheckResult couldNotTell(QString why) const;
    // A request that failed: refused by the device or answered otherwise
    // than we read (refuted), or no answer that decides it (could not tell).
    CheckResult failed(const Error& error) const;
};

// The gate's reason for a request that does not only read.
QString notReadingRequest(const comm::Request& request);

struct CheckReport {
    QString familyId;
    QString protocolId;
    QString device;  // identify() of the device, or why it failed
    QList<CheckResult> results;
    // Requests the gate kept off the line: a check that tried to write (a
    // bug of ours, never sent). Counted so that the report says so.
    int refusedRequests = 0;
    int requestsSent = 0;

    int count(CheckVerdict verdict) const;
    bool anyRefuted() const { return count(CheckVerdict::Refuted) > 0; }
};

// One line per verdict ("held      ascii.?NF  ..."), then the tally.
QString checkReportText(const CheckReport& report);
// The report to send back: family, protocol, device, the verdicts.
QJsonObject checkReportJson(const CheckReport& report);

// A table the check tries instead of the one the device holds: read and
// parsed before anything is sent, handed to the connection (of `familyId`)
// just before the check runs.
struct CheckTable {
    QString familyId;
    QString option;  // "--parameters", for the message of a wrong family
    std::function<void(comm::DeviceConnection& connection)> use;
};

// A file option of a family's check ("--parameters FILE": the MC-1's axis
// parameter table): `load` reads and parses the file, or says why not.
struct CheckTableOption {
    QString option;
    std::function<Result<CheckTable>(const QString& path)> load;
};

// One family's checks. `refuses` is the gate: a non-empty reason for any
// request of `protocolId` that is not a reading one; `run` gets the
// connection only after the gate is on its engine. The tables a check
// tries are those the connection holds (what the person loaded, or the
// built-in provisional ones); `tables` name the files that replace them.
struct FamilyCheck {
    QString familyId;
    std::function<QString(const QString& protocolId, const comm::Request& request)> refuses;
    std::function<Result<QList<CheckResult>>(comm::DeviceConnection& connection,
                                             const UseCaseProgress& progress)>
        run;
    QList<CheckTableOption> tables = {};
};

// The families' checks, registered once at start (app/registry).
class CheckRegistry {
public:
    static CheckRegistry& instance();
    void add(FamilyCheck check);
    const FamilyCheck* find(const QString& familyId) const;
    // Every family's table options ("--parameters", "--dictionary").
    QStringList tableOptions() const;
    // The file given with `option` read and parsed (nothing sent): an
    // invalid file is an InvalidData error naming it.
    Result<CheckTable> loadTable(const QString& option, const QString& path) const;

private:
    QList<FamilyCheck> m_checks;
};

// Runs the check of the connection's family (inside a worker job), with
// the gate on the engine for its whole run. A family without checks is a
// Usage error naming it.
// `tables` replace the connection's own before anything is sent; a table
// of another family is a Usage error naming its option.
Result<CheckReport> checkDevice(comm::DeviceConnection& connection,
                                const UseCaseProgress& progress = {},
                                const QList<CheckTable>& tables = {});

}  // namespace cambench::usecases
