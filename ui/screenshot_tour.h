#pragma once

#include "family_gui.h"

#include <QMetaObject>
#include <QObject>
#include <QString>
#include <QStringList>

namespace cambench {

class MainWindow;
class Shell;

// The stop "01-connection" after a bus scan (point to point: the device
// identified): ready once a device is listed and `ready` (if given) holds.
TourStop scannedConnectionStop(MainWindow* window, std::function<bool()> ready = {});

// `cambench --screenshots DIR`: connects to every device the registered
// families name for the tour (each family's protocols on their in-process
// simulated devices) in turn, visits each one's stops, waits through the
// event loop for their data (never sleeping on the GUI thread), saves one
// PNG per stop ("<visit>-<stop>.png") and reports when done. A stop whose
// data does not come, or a device that does not load, is a failure named
// in failures(): the tour never passes by skipping.
class ScreenshotTour : public QObject {
    Q_OBJECT
public:
    ScreenshotTour(Shell* shell, const QString& directory, QObject* parent = nullptr);

    // Visits only the devices named (TourVisit::name); all when empty.
    void keepOnly(const QStringList& visits) { m_only = visits; }
    // The PNGs the tour takes, by file name in order, without connecting.
    QStringList plannedFiles() const;
    // How long a device may take to load, or a stop's data to arrive,
    // before it counts as not reached (tests shorten it).
    void setPatience(int ms) { m_patienceMs = ms; }

    void start();
    QStringList failures() const { return m_failures; }
    // The PNGs saved, by file name, in the order taken.
    QStringList saved() const { return m_saved; }

Q_SIGNALS:
    void finished(bool ok);

private:
    struct Visit {
        FamilyWindow* family;
        TourVisit device;
    };
    QList<Visit> visits() const;
    void runVisit(int index);
    void visitLoaded(bool ok);
    void runStep(int index);
    void waitFor(int index, int waitedMs);
    void capture(int index);
    QString stopName(int index) const;

    Shell* m_shell;
    QString m_directory;
    QStringList m_only;
    int m_patienceMs = 60000;
    QList<Visit> m_visits;
    int m_visit = -1;
    QList<TourStop> m_steps;
    QMetaObject::Connection m_loadWait;
    QStringList m_failures;
    QStringList m_saved;
};

}  // namespace cambench
