#include "shell.h"

#include "connection_page.h"
#include "device_session.h"
#include "family_gui.h"
#include "gui_settings.h"
#include "language.h"
#include "main_window.h"

#include <QScreen>

namespace cambench {

Shell::Shell(QObject* parent) : QObject(parent), m_session(new DeviceSession(this)) {
    for (const FamilyGuiInfo* info : FamilyGuiRegistry::instance().all())
        m_families << info->create(m_session, this);
    // Only a connection that worked is worth remembering for the next start.
    connect(m_session, &DeviceSession::stateChanged, this, [this](comm::ConnectionState state) {
        if (state == comm::ConnectionState::Connected)
            guisettings::saveConnection(m_session->connection(), m_session->protocol());
    });
}

Shell::~Shell() {
    delete m_window;
}

void Shell::showFitting(MainWindow& window, bool restored) {
    // The first time: 1280 x 800, or the whole screen where that would put
    // the status bar (and its connection indicator) below the screen's edge.
    const QScreen* screen = window.screen();
    constexpr int kFrameAllowance = 60;  // title bar and borders of the window manager
    if (!restored && screen &&
        (screen->availableGeometry().height() < window.height() + kFrameAllowance ||
         screen->availableGeometry().width() < window.width())) {
        window.showMaximized();
        return;
    }
    window.show();
}

FamilyGui* Shell::family(const QString& familyId) const {
    for (FamilyGui* family : m_families)
        if (family->familyId() == familyId) return family;
    return nullptr;
}

MainWindow* Shell::createWindow() {
    auto* window = new MainWindow(m_session, m_families);
    connect(window, &MainWindow::languageRequested, this, &Shell::switchLanguage,
            Qt::QueuedConnection);
    return window;
}

void Shell::start(const QString& port, const QString& protocol) {
    m_window = createWindow();
    const int section = guisettings::restoreWindow(*m_window);
    if (section >= 0 && section < m_window->sectionCount()) m_window->showSection(section);
    showFitting(*m_window, section >= 0);
    if (port.isEmpty()) {
        // The last connection that worked, with its protocol and settings.
        const auto remembered = guisettings::loadConnection();
        if (!remembered) return;
        m_window->connectionPage()->showConnection(remembered->connection, *remembered->protocol);
    } else {
        m_window->connectionPage()->setPort(port);
        if (!protocol.isEmpty()) m_window->connectionPage()->setProtocol(protocol);
    }
    m_window->connectAndLoad();
}

void Shell::switchLanguage(const QString& language) {
    setLanguage(language);
    guisettings::setLanguage(currentLanguage());
    if (!m_window) return;
    MainWindow* old = m_window;
    MainWindow* window = createWindow();
    window->setGeometry(old->geometry());
    window->showSection(old->currentSection());
    m_window = window;
    window->show();
    // Deleted now, not later: its pages point at this shell's session, and
    // the shell may be gone before a deferred delete would run. The switch
    // arrives through a queued call, never from inside the old window.
    delete old;
    Q_EMIT windowRebuilt(window);
}

}  // namespace cambench
