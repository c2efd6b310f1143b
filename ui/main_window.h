#pragma once

#include "model/result.h"

#include <QMainWindow>

class QAction;
class QLabel;
class QListWidget;
class QMenu;
class QProgressBar;
class QStackedWidget;
class QToolButton;

namespace cambench {

class BackupWizard;
class CamPage;
class CompareDialog;
class ConnectionIndicator;
class ConnectionPage;
class ConnectionStrip;
class DeadTimesPage;
class DeviceSession;
class LineBackupDialog;
class MonitorPage;
class PlcPage;
class SectionPage;
class SettingsPage;
class TerminalPage;
class UsersPage;
class Workspace;

// The CamBench window: connection panel and the sections of one device
// (cam programs, dead times, encoder & system, users, PLC, monitor, backup,
// terminal). Session and workspace live outside it: the window can be
// rebuilt (language switch) without losing the line or an edit.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    enum Section {
        Connection,
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

    MainWindow(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);
    ~MainWindow() override;

    void showSection(Section section);
    Section currentSection() const;

    ConnectionPage* connectionPage() const { return m_connection; }
    CamPage* camPage() const { return m_cams; }
    DeadTimesPage* deadTimesPage() const { return m_deadTimes; }
    SettingsPage* settingsPage() const { return m_settings; }
    UsersPage* usersPage() const { return m_users; }
    PlcPage* plcPage() const { return m_plc; }
    MonitorPage* monitorPage() const { return m_monitor; }
    TerminalPage* terminalPage() const { return m_terminal; }
    QList<SectionPage*> dataPages() const;

    // Connect, read the identity, then the settings, names, dead times,
    // users and program `program` (readAtStart); `loaded` says when.
    void connectAndLoad(int program = 0);
    void readAtStart(int program = 0);
    // Device → Read everything: identity, every program and section in one
    // job with one progress bar; `everythingRead` says when.
    void readEverything(int program = 0);

    CompareDialog* openCompare();
    // Device → Last write report: the report of the last write, again.
    void showLastWriteReport();
    BackupWizard* openBackupWizard();
    LineBackupDialog* openLineBackup();
    QString lastMessage() const { return m_lastMessage; }
    // Asks before closing when edits are not written; true = may close.
    bool confirmClose();

    // Refuses while the device is still being read; warns about values a
    // write would refuse, but saves them as they are.
    Status saveProjectTo(const QString& path);
    bool isReadingDevice() const { return m_readJob != 0 || m_startReads > 0; }
    // Opens a project file (asks first when it would replace edits).
    void openProjectFile(const QString& path);
    Status exportReport(const QString& path);
    QMenu* recentFilesMenu() const { return m_recentMenu; }
    ConnectionStrip* connectionStrip() const { return m_strip; }
    ConnectionIndicator* connectionIndicator() const { return m_indicator; }

Q_SIGNALS:
    void languageRequested(const QString& language);
    void darkRequested(bool dark);
    // The identity (and the first program) arrived after connectAndLoad.
    void loaded(bool ok);
    void everythingRead(bool ok);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createPages();
    void createMenus();
    void createStatusBar();
    void showMessage(const QString& text);
    void fillRecentFiles();
    void updateLivePolling();
    void updateTitle();
    void updateConnection();
    // Shows the pages of the family the session's protocol belongs to and
    // hides the others'.
    void showFamilyPages();
    // Connected to a device of another family than the CamCon: its identity,
    // for the status bar and `loaded`.
    void identifyOtherFamily();
    // Identifies the device on the line (checkConnectedDevice), then reads
    // the start sections when a load is pending or another device answers.
    void checkDevice();
    void readStartSections(int program);
    void updateLastWriteButton();
    void newProject();
    void openProject();
    void saveProject();
    void saveProjectAs();
    void exportReportInteractive();

    DeviceSession* m_session;
    Workspace* m_workspace;
    QListWidget* m_nav;
    QStackedWidget* m_stack;
    ConnectionStrip* m_strip;
    ConnectionIndicator* m_indicator;
    QMenu* m_recentMenu = nullptr;
    QLabel* m_jobLabel;
    QProgressBar* m_jobProgress;
    QToolButton* m_jobCancel;
    QToolButton* m_lastWrite;
    quint64 m_runningJob = 0;  // the user job the status bar shows
    ConnectionPage* m_connection = nullptr;
    CamPage* m_cams = nullptr;
    DeadTimesPage* m_deadTimes = nullptr;
    SettingsPage* m_settings = nullptr;
    UsersPage* m_users = nullptr;
    PlcPage* m_plc = nullptr;
    MonitorPage* m_monitor = nullptr;
    TerminalPage* m_terminal = nullptr;
    QList<SectionPage*> m_pages;
    QList<QString> m_pageFamilies;  // per page: its family, empty for the shell's
    QString m_lastMessage;
    int m_pendingProgram = -1;
    quint64 m_readJob = 0;  // the whole-device read running, 0 = none
    int m_startReads = 0;   // reads of readAtStart() still running
};

}  // namespace cambench
