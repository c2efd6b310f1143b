#include "last_write_report.h"

namespace cambench {

void LastWriteReport::record(const QString& title, const QString& summary, const QString& details,
                             bool complete) {
    m_title = title;
    m_summary = summary;
    m_details = details;
    m_complete = complete;
    m_when = QDateTime::currentDateTime();
    Q_EMIT changed();
}

}  // namespace cambench
