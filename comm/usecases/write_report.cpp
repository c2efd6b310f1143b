#include "write_report.h"

namespace cambench::usecases {

QList<OutcomeLine> WriteReport::lines() const {
    QList<OutcomeLine> lines;
    const auto add = [&lines](const auto& outcomes) {
        for (const auto& outcome : outcomes) lines.append(outcomeLine(outcome));
    };
    add(settings);
    add(programNames);
    add(tracks);
    add(deadTimes);
    add(deadTimeModes);
    add(outputNames);
    add(users);
    add(plcNetworks);
    return lines;
}

}  // namespace cambench::usecases
