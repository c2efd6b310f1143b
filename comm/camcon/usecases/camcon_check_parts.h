#pragma once

// The CamCon check's parts, one per protocol (camcon_check_*.cpp).

#include "comm/usecases/device_check.h"

#include <optional>

namespace cambench::comm {
class AsciiCamCon;
namespace table {
class TableCamCon;
}
}  // namespace cambench::comm

namespace cambench::usecases::camcon_check {

// Each '?' command of the catalogue, numbers as 0 (the first program,
// output, channel, block): answered and decoded as the catalogue reads it.
Result<QList<CheckResult>> catalogueQueries(comm::AsciiCamCon& device,
                                            const UseCaseProgress& progress);
// Multiuser: a block number is taken, a repeated one is answered again.
Result<QList<CheckResult>> multiuserNumbering(comm::AsciiCamCon& device);
// Cam-BUS, listening only: the token goes round every user of the table.
Result<QList<CheckResult>> camBusTiming(comm::AsciiCamCon& device);
// The first word of each readable run of the table map (area 203 word 38
// first: only the analogue areas the device says it has).
Result<QList<CheckResult>> tableAreas(comm::table::TableCamCon& device,
                                      const UseCaseProgress& progress);

// After a few unanswered requests in a row the line is taken for gone: the
// rest are "could not tell" without waiting for each.
class SilentLine {
public:
    // Could not tell, without asking, once the line is taken for gone.
    std::optional<CheckResult> skip(const Reading& reading) const;
    // Whether the request just made was answered (anything but a line failure).
    void answered(bool heard) { m_silent = heard ? 0 : m_silent + 1; }

private:
    static constexpr int kGiveUpAfter = 3;
    int m_silent = 0;
};

}  // namespace cambench::usecases::camcon_check
