#pragma once

#include "comm/traffic/traffic_entry.h"

#include <QSaveFile>
#include <QString>

namespace cambench::cli {

// The --log file: one formatted line per frame sent or received (user
// numbers already masked by the link). Written atomically when the run ends,
// so a reader never sees half a log.
class TrafficLogFile {
public:
    explicit TrafficLogFile(const QString& path);
    ~TrafficLogFile();

    void append(const comm::TrafficEntry& entry);
    void note(const QString& text);  // "# text" line

private:
    QSaveFile m_file;
    bool m_ok = false;
};

}  // namespace cambench::cli
