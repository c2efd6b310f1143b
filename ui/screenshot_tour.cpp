#include "screenshot_tour.h"

#include "device_session.h"
#include "family_gui.h"
#include "main_window.h"
#include "shell.h"
#include "shell_log.h"

#include <QDir>
#include <QListWidget>
#include <QPainter>
#include <QTimer>

namespace cambench {

namespace {
const QSize kWindowSize(1280, 800);
constexpr int kStepTimeoutMs = 60000;
constexpr int kPollMs = 100;
}  // namespace

ScreenshotTour::ScreenshotTour(Shell* shell, const QString& directory, QObject* parent)
    : QObject(parent), m_shell(shell), m_directory(directory) {}

void ScreenshotTour::start() {
    QDir().mkpath(m_directory);
    m_shell->window()->resize(kWindowSize);
    buildSteps();
    runStep(0);
}

void ScreenshotTour::buildSteps() {
    // The stops are the connected family's: its pages, its dialogs.
    MainWindow* window = m_shell->window();
    FamilyWindow* family = window->familyWindow(sessionFamily(*m_shell->session()));
    m_steps = family ? family->tourStops(m_directory) : QList<TourStop>{};
    if (m_steps.isEmpty())
        m_failures << QStringLiteral("no screens to visit: no family page knows the device");
}

void ScreenshotTour::runStep(int index) {
    if (index >= m_steps.size()) {
        Q_EMIT finished(m_failures.isEmpty());
        return;
    }
    m_steps[index].prepare();
    waitFor(index, 0);
}

void ScreenshotTour::waitFor(int index, int waitedMs) {
    const TourStop& step = m_steps[index];
    if (!step.ready() && waitedMs < kStepTimeoutMs) {
        QTimer::singleShot(kPollMs, this,
                           [this, index, waitedMs] { waitFor(index, waitedMs + kPollMs); });
        return;
    }
    if (waitedMs >= kStepTimeoutMs) {
        m_failures << QStringLiteral("%1: its data did not arrive within %2 s (%3)")
                          .arg(step.name)
                          .arg(kStepTimeoutMs / 1000)
                          .arg(m_shell->window()->lastMessage());
    }
    // One more round of the event loop so the page paints what arrived.
    QTimer::singleShot(300, this, [this, index] {
        capture(index);
        runStep(index + 1);
    });
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
    const QString path = QDir(m_directory).filePath(m_steps[index].name + QStringLiteral(".png"));
    if (!shot.save(path))
        m_failures << QStringLiteral("%1: cannot write %2").arg(m_steps[index].name, path);
    qCInfo(shellLog) << "screenshot" << path;
}

}  // namespace cambench
