#pragma once

#include "comm/device/id_registry.h"
#include "model/result.h"

#include <QList>
#include <QObject>
#include <QString>

#include <functional>

class QMenu;
class QTextDocument;
class QWidget;

namespace cambench {

class DeviceSession;
class FamilyWindow;
class MainWindow;
class SectionPage;

// One device family's part of the GUI for the whole run. What the family
// holds on the PC (the CamCon's edits) lives here: it outlives a window
// rebuilt on a language switch. The shell makes one per registered family
// and asks it for its part of each window it builds.
class FamilyGui : public QObject {
    Q_OBJECT
public:
    FamilyGui(QString familyId, DeviceSession* session, QObject* parent = nullptr);

    QString familyId() const { return m_familyId; }
    DeviceSession* session() const { return m_session; }

    // The family's pages, menu entries and start reads in `window`.
    virtual FamilyWindow* createWindow(MainWindow* window) = 0;
    // The connected device for the connection strip ("CamCon 11.10.1994,
    // device number 0."; a second line may follow); empty until it has
    // identified itself.
    virtual QString identityLine() const { return m_identity; }
    // What the window's title names when no file does: the device, or
    // what is being edited ("offline project"); empty = nothing.
    virtual QString windowSubject() const { return {}; }
    // Edits on this PC that are not on the device.
    virtual int unwrittenCount() const { return 0; }
    // Reads from the device on the line what reportSection() shows - all
    // of it, not only what its pages happened to read - on the session's
    // worker, then calls `done` on `parent`'s thread (an error: what could
    // not be read; the section then says "not read" where it lacks a
    // value). `parent` carries a question the read may ask (edits on this
    // PC that a read would replace). The default reads nothing.
    virtual void readForReport(QWidget* parent, std::function<void(const Status&)> done);
    // The family's section of a machine's report (HTML; pictures added to
    // `document` under names that begin with `resourcePrefix`): what the
    // PC holds of the device and when it was read. Empty: the family has
    // no report of its own (the section has the shell's lines only).
    virtual QString reportSection(QTextDocument& document, const QString& resourcePrefix) const {
        Q_UNUSED(document);
        Q_UNUSED(resourcePrefix);
        return {};
    }
    // Two backups of one of the family's devices - files its FamilyBackup
    // saved, `older` first, each named for the person by its label
    // ("version 1a2b3c4d5e") - drawn in the family's own terms where a
    // table of differences says too little (the CamCon: each program whose
    // cams differ, one over the other). The files are read at once; the
    // widget is the caller's. nullptr: the family draws none, or nothing of
    // what it draws differs (the table says all).
    struct BackupSide {
        QString path;
        QString label;
    };
    virtual QWidget* backupDrawing(const BackupSide& older, const BackupSide& newer) const {
        Q_UNUSED(older);
        Q_UNUSED(newer);
        return nullptr;
    }
    // A family that keeps no identity of its own stores what identify() said.
    void setIdentity(const QString& identity);

Q_SIGNALS:
    void identityChanged();
    // windowSubject() or unwrittenCount() changed.
    void titleChanged();

private:
    QString m_familyId;
    DeviceSession* m_session;
    QString m_identity;
};

// One device `cambench --screenshots DIR` connects to for a family's pages:
// one of its protocols on the in-process simulated device. The PNGs of its
// stops are named "<name>-<stop>.png".
struct TourVisit {
    QString name;      // family and protocol: "<family>-<protocol>", e.g. "fake-line"
    QString port;      // "sim:protocol=3964r-n96;baud=115200"
    QString protocol;  // a registry id: "3964r-n96"
    int device = -1;   // on a bus: the device addressed (-1: the protocol's default)
};

// One stop of `cambench --screenshots DIR`: what to show, when its data has
// arrived, and a dialog drawn over the window.
struct TourStop {
    QString name;  // the PNG's name after the visit's: "02-cam-editor"
    std::function<void()> prepare;
    std::function<bool()> ready;
    std::function<QWidget*()> overlay;
};

// The window's menus a family adds its entries to. They show while the
// session's protocol belongs to the family, like its pages.
struct FamilyMenus {
    QMenu* file;
    QMenu* edit;
    QMenu* device;
    QMenu* tools;
};

// A family's part of one main window: its pages, its menu entries, what it
// reads when one of its devices comes on the line.
class FamilyWindow : public QObject {
    Q_OBJECT
public:
    FamilyWindow(FamilyGui* gui, MainWindow* window);

    FamilyGui* gui() const { return m_gui; }
    MainWindow* window() const { return m_window; }

    // In the order of the window's list; made once, owned by the window.
    virtual QList<SectionPage*> pages() const = 0;
    virtual void addMenuEntries(const FamilyMenus& menus) { Q_UNUSED(menus); }
    // What the connection page shows of the connected (or last) device;
    // nullptr: nothing beyond the connection strip's line.
    virtual QWidget* identityPanel() { return nullptr; }
    // A device of this family is on the line (a connect, a reconnect,
    // another bus device chosen): find out which, and, when `load`, read
    // what a person looks at first; then window()->reportLoaded(ok).
    // The default asks the device to identify itself.
    virtual void deviceOnLine(bool load);
    // A device came on the line (this family's or another's): the shell
    // asks every family first to forget the one before. The default drops
    // the identity and has each page forget (SectionPage::forgetDevice);
    // a family that keeps more of its device (facts) drops that too.
    virtual void forgetDevice();
    // Another page became current (live values poll only where shown).
    virtual void pageShown(SectionPage* page) { Q_UNUSED(page); }
    // Asked before the window closes; false keeps it open.
    virtual bool confirmClose() { return true; }
    // The devices the screenshot tour connects to for this family: one per
    // protocol that shows pages or views of its own.
    virtual QList<TourVisit> tourVisits() const { return {}; }
    // The tour's stops on `visit` (one of tourVisits()) once its device is
    // on the line and loaded; a stop may write files into `directory`.
    virtual QList<TourStop> tourStops(const TourVisit& visit, const QString& directory) {
        Q_UNUSED(visit);
        Q_UNUSED(directory);
        return {};
    }
    // After the last stop of `visit`: puts back what its stops changed on
    // the PC (edits), so that the next device is met as a person would.
    virtual void tourVisitDone(const TourVisit& visit) { Q_UNUSED(visit); }

private:
    FamilyGui* m_gui;
    MainWindow* m_window;
};

// A family's GUI, registered by the GUI part of its FamilyParts (app/registry).
struct FamilyGuiInfo {
    QString familyId;
    std::function<FamilyGui*(DeviceSession* session, QObject* parent)> create;
};

class FamilyGuiRegistry : public comm::IdRegistry<FamilyGuiInfo, &FamilyGuiInfo::familyId> {
public:
    static FamilyGuiRegistry& instance();
};

// Each registered family's part for `session`, in registration order (what
// one device's window shows: the shell's, or one device's of a machine).
QList<FamilyGui*> createFamilyGuis(DeviceSession* session, QObject* parent);

// The family of the protocol `session` connects (or last connected) with.
QString sessionFamily(const DeviceSession& session);

}  // namespace cambench
