#pragma once

#include "cli_session.h"

#include "comm/usecases/write_items.h"

namespace cambench::cli {

// Runs `plan` (made by `makePlan` inside the job, after the device's
// identity was read) through the one write path and prints the outcome of
// every item, then the summary. Exit 0 only when every item was written or
// unchanged; a refused plan exits 4 before anything was sent.
int runWritePlan(
    CliSession& session, const QString& title,
    std::function<Result<usecases::WritePlan>(comm::CamConDevice&, const DeviceInfo&)> makePlan);

// Prints the report: one line per item on stdout, the summary last; when
// not everything was written the summary also goes to stderr. Returns the
// exit code.
int printWriteReport(const usecases::WriteReport& report);

}  // namespace cambench::cli
