#include "shell.h"

#include "connection_page.h"
#include "device_session.h"
#include "language.h"
#include "main_window.h"
#include "workspace.h"

namespace cambench {

Shell::Shell(QObject* parent)
    : QObject(parent), m_session(new DeviceSession(this)), m_workspace(new Workspace(this)) {}

Shell::~Shell() { delete m_window; }

MainWindow* Shell::createWindow() {
    auto* window = new MainWindow(m_session, m_workspace);
    connect(window, &MainWindow::languageRequested, this, &Shell::switchLanguage, Qt::QueuedConnection);
    return window;
}

void Shell::start(const QString& port) {
    m_window = createWindow();
    m_window->show();
    if (port.isEmpty()) return;
    m_window->connectionPage()->setPort(port);
    m_window->connectAndLoad(0);
}

void Shell::switchLanguage(const QString& language) {
    setLanguage(language);
    if (!m_window) return;
    MainWindow* old = m_window;
    MainWindow* window = createWindow();
    window->setGeometry(old->geometry());
    window->showSection(old->currentSection());
    m_window = window;
    window->show();
    old->hide();
    old->deleteLater();
    Q_EMIT windowRebuilt(window);
}

}  // namespace cambench
