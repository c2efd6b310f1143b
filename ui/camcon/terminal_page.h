#pragma once

#include "ui/camcon/camcon_section_page.h"

#include "comm/camcon/ascii/ascii_link.h"

class QCheckBox;
class QLineEdit;
class QPlainTextEdit;

namespace cambench {

class DeviceSession;

// Raw commands for diagnosis (the checksum is added by the link) and the
// live traffic log: timestamps, hex and ASCII, user numbers masked by the
// link before they get here. The log can be saved to a file.
class TerminalPage : public CamConSectionPage {
    Q_OBJECT
public:
    explicit TerminalPage(DeviceSession* session, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Terminal"); }

    void send(const QString& command);
    Status saveLog(const QString& path) const;
    QString logText() const;

private:
    void appendTraffic(const comm::TrafficEntry& entry);

    DeviceSession* m_session;
    QLineEdit* m_command;
    QPlainTextEdit* m_replies;
    QPlainTextEdit* m_log;
    QCheckBox* m_follow;
};

}  // namespace cambench
