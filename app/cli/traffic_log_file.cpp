#include "traffic_log_file.h"

#include "cli_output.h"

#include "comm/traffic/traffic_log.h"

namespace cambench::cli {

TrafficLogFile::TrafficLogFile(const QString& path) : m_file(path) {
    m_ok = m_file.open(QIODevice::WriteOnly | QIODevice::Text);
    if (!m_ok) {
        printError(QStringLiteral("cannot write the log %1 (%2); continuing without a log")
                       .arg(path, m_file.errorString()));
    }
}

TrafficLogFile::~TrafficLogFile() {
    if (m_ok && !m_file.commit()) {
        printError(QStringLiteral("cannot save the log %1 (%2)")
                       .arg(m_file.fileName(), m_file.errorString()));
    }
}

void TrafficLogFile::append(const comm::TrafficEntry& entry) {
    if (m_ok) m_file.write(comm::formatTrafficEntry(entry).toUtf8() + '\n');
}

void TrafficLogFile::note(const QString& text) {
    if (m_ok) m_file.write("# " + text.toUtf8() + '\n');
}

}  // namespace cambench::cli
