#pragma once

#include "mc1_report.h"

#include "ui/family_gui.h"

#include <optional>

namespace cambench {

class Mc1WatchModel;

// The MC-1 family's part of the GUI for the whole run: the watch list
// (variables and their names, kept across a window rebuilt on a language
// switch).
class Mc1Gui : public FamilyGui {
    Q_OBJECT
public:
    Mc1Gui(DeviceSession* session, QObject* parent = nullptr);

    Mc1WatchModel* watchList() const { return m_watch; }
    FamilyWindow* createWindow(MainWindow* window) override;
    QString windowSubject() const override { return identityLine(); }
    void readForReport(QWidget* parent, std::function<void(const Status&)> done) override;
    QString reportSection(QTextDocument& document, const QString& resourcePrefix) const override;

private:
    Mc1WatchModel* m_watch;
    std::optional<Mc1ReportReading> m_report;  // the last reading for a report
};

}  // namespace cambench
