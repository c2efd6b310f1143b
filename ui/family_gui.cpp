#include "family_gui.h"

#include "device_session.h"
#include "main_window.h"
#include "section_page.h"
#include "sentence.h"

#include "comm/device/protocol_registry.h"

namespace cambench {

FamilyGui::FamilyGui(QString familyId, DeviceSession* session, QObject* parent)
    : QObject(parent), m_familyId(std::move(familyId)), m_session(session) {}

void FamilyGui::readForReport(QWidget* parent, std::function<void(const Status&)> done) {
    Q_UNUSED(parent);
    done(success());
}

void FamilyGui::setIdentity(const QString& identity) {
    if (identity == m_identity) return;
    m_identity = identity;
    Q_EMIT identityChanged();
}

FamilyWindow::FamilyWindow(FamilyGui* gui, MainWindow* window)
    : QObject(window), m_gui(gui), m_window(window) {}

void FamilyWindow::deviceOnLine(bool load) {
    m_gui->setIdentity({});
    m_gui->session()->setDeviceChecked(false);
    m_gui->session()->worker().run<Result<QString>>(
        this, comm::JobPriority::User, MainWindow::tr("Identify device"),
        [](comm::JobContext& job) -> Result<QString> {
            if (!job.device()) return Error::communication(MainWindow::tr("not connected"));
            return job.device()->identify();
        },
        [this, load](Result<QString> identity) {
            if (identity) {
                m_gui->setIdentity(*identity);
                m_gui->session()->setDeviceChecked(true);
            } else if (identity.error().kind != ErrorKind::Cancelled) {
                m_gui->session()->setIdentifyFailed(identity.error().message);
            }
            m_window->showMessage(identity
                                      ? MainWindow::tr("Connected: %1").arg(*identity)
                                      : MainWindow::tr("The device did not identify itself: %1")
                                            .arg(asSentence(identity.error().message)));
            if (load) m_window->reportLoaded(identity.ok());
        });
}

void FamilyWindow::forgetDevice() {
    m_gui->setIdentity({});
    for (SectionPage* page : pages()) page->forgetDevice();
}

FamilyGuiRegistry& FamilyGuiRegistry::instance() {
    static FamilyGuiRegistry registry;
    return registry;
}

QList<FamilyGui*> createFamilyGuis(DeviceSession* session, QObject* parent) {
    QList<FamilyGui*> families;
    for (const FamilyGuiInfo* info : FamilyGuiRegistry::instance().all())
        families << info->create(session, parent);
    return families;
}

QString sessionFamily(const DeviceSession& session) {
    const comm::ProtocolInfo* info =
        comm::ProtocolRegistry::instance().find(session.protocol().protocolId());
    return info ? info->familyId : QString();
}

}  // namespace cambench
