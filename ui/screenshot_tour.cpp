#include "screenshot_tour.h"

#include "connection_page.h"
#include "device_session.h"
#include "family_gui.h"
#include "main_window.h"
#include "shell.h"
#include "shell_log.h"

#include <QApplication>
#include <QDir>
#include <QListWidget>
#include <QPainter>
#include <QTimer>

namespace cambench {

namespace {
const QSize kWindowSize(1280, 800);
constexpr int kPollMs = 100;

// The name of a stop's PNG without ".png": "<visit>-<number>-<stop>".
QString shotName(const TourVisit& visit, const TourStop& stop) {
    return visit.name + u'-' + stop.name;
}
}  // namespace

TourStop scannedConnectionStop(MainWindow* window, std::function<bool()> ready) {
    auto* devices = window->connectionPage()->findChild<QListWidget*>();
    return {QStringLiteral("01-connection"),
            [window] {
                window->showSection(MainWindow::Connection);
                window->connectionPage()->scanBus();
            },
            [devices, ready = std::move(ready)] {
                return devices && devices->count() > 0 && (!ready || ready());
            },
            {}};
}

ScreenshotTour::ScreenshotTour(Shell* shell, const QString& directory, QObject* parent)
    : QObject(parent), m_shell(shell), m_directory(directory) {}

void ScreenshotTour::start() {
    QDir().mkpath(m_directory);
    // The same size on every screen: not maximized to a small one.
    m_shell->window()->showNormal();
    m_shell->window()->resize(kWindowSize);
    // The tour moves nothing: it goes from device to device without the
    // question a person gets before leaving one that can move.
    m_shell->session()->setLeaveCheck(this, [](const QString&) { return true; });
    m_visits = visits();
    if (m_visits.isEmpty()) {
        m_failures << QStringLiteral("no screens to visit: no family names a device for the tour");
        Q_EMIT finished(false);
        return;
    }
    runVisit(0);
}

QList<ScreenshotTour::Visit> ScreenshotTour::visits() const {
    // The families in the window's order, each with the devices it names.
    QList<Visit> visits;
    MainWindow* window = m_shell->window();
    for (const FamilyGui* family : m_shell->families()) {
        FamilyWindow* part = window->familyWindow(family->familyId());
        if (!part) continue;
        for (const TourVisit& device : part->tourVisits())
            if (m_only.isEmpty() || m_only.contains(device.name)) visits << Visit{part, device};
    }
    return visits;
}

QStringList ScreenshotTour::plannedFiles() const {
    QStringList files;
    for (const Visit& visit : visits())
        for (const TourStop& stop : visit.family->tourStops(visit.device, m_directory))
            files << shotName(visit.device, stop) + QStringLiteral(".png");
    return files;
}

void ScreenshotTour::runVisit(int index) {
    m_visit = index;
    m_steps.clear();
    if (index >= m_visits.size()) {
        Q_EMIT finished(m_failures.isEmpty());
        return;
    }
    const TourVisit& device = m_visits[index].device;
    MainWindow* window = m_shell->window();
    window->showSection(MainWindow::Connection);
    window->connectionPage()->setPort(device.port);
    window->connectionPage()->setProtocol(device.protocol);
    if (device.device >= 0) {
        ConnectionPage* page = window->connectionPage();
        std::unique_ptr<comm::ProtocolSettings> settings = page->protocolSettings()->clone();
        settings->setDevice(device.device);
        page->showConnection(page->connectionSettings(), *settings);
    }
    m_loadWait = connect(window, &MainWindow::loaded, this, &ScreenshotTour::visitLoaded,
                         Qt::SingleShotConnection);
    window->connectAndLoad();
    QTimer::singleShot(m_patienceMs, this, [this, index] {
        if (m_visit != index || !m_steps.isEmpty() || !m_loadWait) return;
        disconnect(m_loadWait);
        visitLoaded(false);
    });
}

void ScreenshotTour::visitLoaded(bool ok) {
    const Visit& visit = m_visits[m_visit];
    qCInfo(shellLog) << "tour:" << visit.device.name << (ok ? "loaded" : "not loaded");
    m_steps = visit.family->tourStops(visit.device, m_directory);
    if (ok && !m_steps.isEmpty()) {
        runStep(0);
        return;
    }
    // Every stop of a device that did not come is named as not taken.
    QStringList names;
    for (int i = 0; i < m_steps.size(); ++i) names << stopName(i);
    QString why = m_shell->window()->lastMessage();
    if (QWidget* question = QApplication::activeModalWidget()) {
        // A question nobody answers: named, and closed so the tour goes on.
        why = QStringLiteral("\"%1\" waits for an answer").arg(question->windowTitle());
        question->close();
    }
    m_failures << QStringLiteral("%1 (%2 on %3): the device did not load (%4); not taken: %5")
                      .arg(visit.device.name, visit.device.protocol, visit.device.port, why,
                           names.isEmpty() ? QStringLiteral("its stops") : names.join(u", "));
    m_steps.clear();
    runVisit(m_visit + 1);
}

void ScreenshotTour::runStep(int index) {
    if (index >= m_steps.size()) {
        const Visit& visit = m_visits[m_visit];
        visit.family->tourVisitDone(visit.device);
        runVisit(m_visit + 1);
        return;
    }
    m_steps[index].prepare();
    waitFor(index, 0);
}

void ScreenshotTour::waitFor(int index, int waitedMs) {
    const TourStop& step = m_steps[index];
    if (!step.ready() && waitedMs < m_patienceMs) {
        QTimer::singleShot(kPollMs, this,
                           [this, index, waitedMs] { waitFor(index, waitedMs + kPollMs); });
        return;
    }
    if (waitedMs >= m_patienceMs) {
        m_failures << QStringLiteral("%1: its data did not arrive within %2 s (%3)")
                          .arg(stopName(index))
                          .arg(m_patienceMs / 1000.0)
                          .arg(m_shell->window()->lastMessage());
    }
    // One more round of the event loop so the page paints what arrived.
    QTimer::singleShot(300, this, [this, index] {
        capture(index);
        runStep(index + 1);
    });
}

QString ScreenshotTour::stopName(int index) const {
    return shotName(m_visits[m_visit].device, m_steps[index]);
}

void ScreenshotTour::capture(int index) {
    MainWindow* w = m_shell->window();
    QPixmap shot = w->grab();
    if (const auto& overlay = m_steps[index].overlay) {
        QWidget* dialog = overlay();
        const QPixmap top = dialog->grab();
        QPainter painter(&shot);
        painter.fillRect(shot.rect(), QColor(0, 0, 0, 80));
        const QPoint at((shot.width() - top.width()) / 2, (shot.height() - top.height()) / 2);
        painter.drawPixmap(at, top);
        painter.setPen(w->palette().color(QPalette::Mid));
        painter.drawRect(QRect(at, top.size()).adjusted(-1, -1, 0, 0));
    }
    const QString file = stopName(index) + QStringLiteral(".png");
    const QString path = QDir(m_directory).filePath(file);
    if (!shot.save(path)) {
        m_failures << QStringLiteral("%1: cannot write %2").arg(stopName(index), path);
        return;
    }
    m_saved << file;
    qCInfo(shellLog) << "screenshot" << path;
}

}  // namespace cambench
