#include "camcon_identity_panel.h"

#include "workspace.h"

#include "ui/device_session.h"

#include <QFormLayout>
#include <QLabel>
#include <QLocale>

namespace cambench {

CamConIdentityPanel::CamConIdentityPanel(DeviceSession* session, Workspace* workspace,
                                         QWidget* parent)
    : QWidget(parent), m_session(session), m_workspace(workspace), m_info(new QFormLayout(this)) {
    m_info->setContentsMargins(0, 0, 0, 0);
    connect(m_session, &DeviceSession::stateChanged, this, &CamConIdentityPanel::showInfo);
    connect(m_session, &DeviceSession::deviceCheckedChanged, this, &CamConIdentityPanel::showInfo);
    connect(m_workspace, &Workspace::infoChanged, this, &CamConIdentityPanel::showInfo);
    showInfo();
}

void CamConIdentityPanel::showInfo() {
    while (m_info->rowCount() > 0) m_info->removeRow(0);
    const DeviceInfo& info = m_workspace->info();
    const bool checked = m_session->isOnline() && m_session->deviceChecked();
    // Offline (or not yet identified), the identity is the last device's,
    // not necessarily the one on the port chosen now: greyed, and said.
    setEnabled(checked || !m_workspace->infoFromDevice());
    if (!m_workspace->infoFromDevice()) {
        m_info->addRow(new QLabel(tr("Not read from a device (offline project).")));
    } else if (!checked) {
        const QDateTime at =
            m_workspace->readTimes().parts.value(ProjectPart::Device).toLocalTime();
        auto* last = new QLabel(
            tr("Last connected: CamCon %1, device number %2, at %3. Not necessarily the device "
               "on the port chosen now.")
                .arg(info.epromDate)
                .arg(info.deviceNumber)
                .arg(QLocale().toString(at.time(), QLocale::ShortFormat)));
        last->setWordWrap(true);
        m_info->addRow(last);
    }
    const QString units = tr("%1 … %2");
    const auto row = [this](const QString& label, const QString& value) {
        auto* text = new QLabel(value);
        text->setTextInteractionFlags(Qt::TextSelectableByMouse);
        m_info->addRow(label, text);
    };
    if (m_workspace->infoFromDevice()) {
        row(tr("Firmware (EPROM date):"), info.epromDate);
        row(tr("Device number:"), QString::number(info.deviceNumber));
    }
    row(tr("Outputs:"), QString::number(info.outputs));
    row(tr("Inputs:"), QString::number(info.inputs));
    row(tr("Programs:"), tr("0 … %1").arg(info.programs - 1));
    row(tr("Position range:"), units.arg(info.minPosition).arg(info.maxPosition));
    row(tr("Outputs with dead time:"), QString::number(info.deadTimeOutputs));
    row(tr("Maximum dead time:"),
        tr("%1 ms").arg(QLocale().toString(info.maxDeadTime / 10.0, 'f', 1)));
    if (m_workspace->infoFromDevice()) {
        row(tr("Programmed cams:"), QString::number(info.programmedCams));
        row(tr("Free cam memory:"), tr("%n cam(s)", nullptr, int(info.freeCams)));
        row(tr("CPU clock:"), info.cpuClock == 1 ? tr("25.2 MHz") : tr("16.7 MHz"));
        row(tr("Temperature:"),
            info.temperature == 255 ? tr("no sensor") : tr("%1 °C").arg(info.temperature));
    }
}

}  // namespace cambench
