#pragma once

#include "model/result.h"

#include <QMainWindow>
#include <QSet>

class QLabel;
class QListWidget;
class QMenu;
class QProgressBar;
class QStackedWidget;
class QToolButton;

namespace cambench {

class ConnectionIndicator;
class ConnectionPage;
class ConnectionStrip;
class DeviceSession;
class FamilyGui;
class FamilyWindow;
class SectionPage;
class StopBar;
class StopControl;

// The CamBench window: the connection page, then the pages of every
// registered device family (those of the family the session's protocol
// belongs to show, the others hide), the menus, the connection strip and
// the status bar. Session and families' data live outside it: the window
// can be rebuilt (language switch) without losing the line or an edit.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // The shell's own page comes first; the families' follow.
    enum Section { Connection = 0 };

    // `machineStop`: the window is one device's of a machine (shown inside
    // the machine's window): its STOP is the machine's, the machine's
    // window has the STOP key and the machine entries of the File menu.
    MainWindow(DeviceSession* session, const QList<FamilyGui*>& families,
               StopControl* machineStop = nullptr, QWidget* parent = nullptr);
    ~MainWindow() override;

    // A page by its row in the list (saved and restored between runs).
    void showSection(int section);
    int currentSection() const;
    int sectionCount() const { return int(m_pages.size()); }
    void showPage(SectionPage* page);
    int rowOf(const SectionPage* page) const { return int(m_pages.indexOf(page)); }

    ConnectionPage* connectionPage() const { return m_connection; }
    ConnectionStrip* connectionStrip() const { return m_strip; }
    ConnectionIndicator* connectionIndicator() const { return m_indicator; }
    // The STOP above every page (hidden while the device cannot move).
    StopBar* stopBar() const { return m_stopBar; }
    // The part of `familyId` ("camcon"), nullptr when not registered.
    FamilyWindow* familyWindow(const QString& familyId) const;
    DeviceSession* session() const { return m_session; }

    // Connects, then has the family of the protocol read what a person
    // looks at first (its identity, its first sections); `loaded` says when.
    void connectAndLoad();
    // The same for the device already on the line (another bus device).
    void readAtStart();
    // A family's reads of connectAndLoad() or readAtStart() are done.
    void reportLoaded(bool ok);

    // Device → Last write report: the report of the last write, again.
    void showLastWriteReport();
    void showMessage(const QString& text);
    QString lastMessage() const { return m_lastMessage; }
    // A job title the status bar does not show (polls would make it flicker).
    void addQuietJobTitle(const QString& title) { m_quietJobs.insert(title); }
    // Asks before closing: what moves (STOP offered), then each family
    // (unwritten edits); true = may close.
    bool confirmClose();

Q_SIGNALS:
    void languageRequested(const QString& language);
    // File → Open machine… / New machine… / Open demo machine.
    void openMachineRequested();
    void newMachineRequested();
    void demoMachineRequested();
    void darkRequested(bool dark);
    // The identity (and the first sections) arrived after connectAndLoad.
    void loaded(bool ok);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createPages(const QList<FamilyGui*>& families);
    void addPage(SectionPage* page, const QString& familyId);
    void createMenus();
    void addMachineEntries(QMenu* file);
    void createStatusBar();
    void updateLivePolling();
    void updateTitle();
    void updateConnection();
    // Shows the pages and menu entries of the family the session's protocol
    // belongs to and hides the others'.
    void showFamilyPages();
    // The family of the session's protocol: its part of this window.
    FamilyWindow* sessionWindow() const;
    // The device on the line is its family's to identify and read.
    void checkDevice();
    void updateLastWriteButton();

    DeviceSession* m_session;
    QListWidget* m_nav;
    QStackedWidget* m_stack;
    ConnectionStrip* m_strip;
    ConnectionIndicator* m_indicator;
    StopBar* m_stopBar;
    QLabel* m_jobLabel;
    QProgressBar* m_jobProgress;
    QToolButton* m_jobCancel;
    QToolButton* m_lastWrite;
    quint64 m_runningJob = 0;  // the user job the status bar shows
    ConnectionPage* m_connection = nullptr;
    QList<FamilyWindow*> m_families;
    QList<SectionPage*> m_pages;
    QList<QString> m_pageFamilies;                    // per page: its family, empty for the shell's
    QList<QPair<QAction*, QString>> m_familyActions;  // menu entries and their family
    QSet<QString> m_quietJobs;
    QString m_lastMessage;
    bool m_loadPending = false;  // connectAndLoad() waits for its family's reads
    bool m_inMachine = false;    // one device's window inside a machine's
};

}  // namespace cambench
