#pragma once

#include "model/result.h"
#include "ui/family_gui.h"

#include <optional>

class QMenu;

namespace cambench {

class BackupWizard;
class CamConGui;
class CamConSectionPage;
class CamPage;
class CompareDialog;
class CompareProgramsDialog;
class DeadTimesPage;
class LineBackupDialog;
class MonitorPage;
class PlcPage;
class SettingsPage;
class TerminalPage;
class UsersPage;
class Workspace;

// The CamCon's part of the main window: its sections (cam programs, dead
// times, encoder & system, users, PLC, monitor, backup, terminal and the
// table interface's own), the project file, Compare, backup and the
// commissioning report in the menus, and the reads when a CamCon comes on
// the line.
class CamConWindow : public FamilyWindow {
    Q_OBJECT
public:
    // The CamCon's pages in list order (after the connection page).
    enum Section {
        Cams,
        DeadTimes,
        Settings,
        Users,
        Plc,
        Monitor,
        Backup,
        Terminal,
        DeadTimeModes,  // the table interface's own sections
        AnalogueCams,
        ProgrammingProgram,
        EepromLock,
        PlcCoupling,
        COUNT
    };

    CamConWindow(CamConGui* gui, MainWindow* window);
    ~CamConWindow() override;

    QList<SectionPage*> pages() const override;
    void addMenuEntries(const FamilyMenus& menus) override;
    QWidget* identityPanel() override;
    void deviceOnLine(bool load) override;
    void pageShown(SectionPage* page) override;
    bool confirmClose() override;
    QList<TourVisit> tourVisits() const override;
    QList<TourStop> tourStops(const TourVisit& visit, const QString& directory) override;
    void tourVisitDone(const TourVisit& visit) override;

    void showSection(Section section);
    // The page of `section` as listed (a CapabilityGate where the protocol
    // may lack the section).
    SectionPage* sectionPage(Section section) const;
    CamPage* camPage() const { return m_cams; }
    DeadTimesPage* deadTimesPage() const { return m_deadTimes; }
    SettingsPage* settingsPage() const { return m_settings; }
    UsersPage* usersPage() const { return m_users; }
    PlcPage* plcPage() const { return m_plc; }
    MonitorPage* monitorPage() const { return m_monitor; }
    // The pages Compare lists differences of.
    QList<CamConSectionPage*> dataPages() const;
    Workspace* workspace() const { return m_workspace; }

    // Device → Read everything: identity, every program and section in one
    // job with one progress bar; `everythingRead` says when.
    void readEverything(int program = 0);
    CompareDialog* openCompare();
    // Tools → Compare programs…
    CompareProgramsDialog* openComparePrograms();
    BackupWizard* openBackupWizard();
    LineBackupDialog* openLineBackup();

    // Refuses while the device is still being read; warns about values a
    // write would refuse, but saves them as they are.
    Status saveProjectTo(const QString& path);
    bool isReadingDevice() const { return m_readJob != 0 || m_startReads > 0; }
    // Opens a project file (asks first when it would replace edits).
    void openProjectFile(const QString& path);
    // `timingSpeed` (axis unit): each program with a table of its timing.
    Status exportReport(const QString& path, std::optional<double> timingSpeed = {});
    QMenu* recentFilesMenu() const { return m_recentMenu; }

Q_SIGNALS:
    void everythingRead(bool ok);

private:
    void createPages();
    // Identifies the device on the line (checkConnectedDevice), then reads
    // the start sections when a load is pending or another device answers.
    void checkDevice();
    void readStartSections(int program);
    void showMessage(const QString& text);
    // The screenshot tour's stops per protocol (camcon_tour.cpp).
    QList<TourStop> standardTourStops(const QString& directory);
    QList<TourStop> tableTourStops();
    QList<TourStop> camBusTourStops();
    // File menu (camcon_window_files.cpp).
    void addFileEntries(QMenu* file);
    void fillRecentFiles();
    void newProject();
    void openProject();
    void saveProject();
    void saveProjectAs();
    void exportReportInteractive();

    CamConGui* m_camcon;
    Workspace* m_workspace;
    QList<SectionPage*> m_pages;  // in Section order
    CamPage* m_cams = nullptr;
    DeadTimesPage* m_deadTimes = nullptr;
    SettingsPage* m_settings = nullptr;
    UsersPage* m_users = nullptr;
    PlcPage* m_plc = nullptr;
    MonitorPage* m_monitor = nullptr;
    TerminalPage* m_terminal = nullptr;
    QWidget* m_identity = nullptr;
    QMenu* m_recentMenu = nullptr;
    int m_pendingProgram = -1;  // a load asked for: the program shown then
    quint64 m_readJob = 0;      // the whole-device read running, 0 = none
    int m_startReads = 0;       // reads of the start still running
};

}  // namespace cambench
