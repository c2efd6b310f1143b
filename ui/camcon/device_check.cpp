#include "device_check.h"
#include "ui/camcon/camcon_jobs.h"

#include "incoming_values.h"
#include "ui/device_session.h"
#include "workspace.h"

#include "comm/camcon/camcon_device.h"

#include <QCoreApplication>
#include <QLocale>
#include <QPointer>
#include <QWidget>

namespace cambench {

namespace {

struct Answer {
    DeviceInfo identity;
    bool users = true;
    bool plc = true;
};

QString identityText(const DeviceInfo& info) {
    return QCoreApplication::translate("cambench::DeviceCheck",
                                       "CamCon %1, device number %2, %3 cams programmed")
        .arg(info.epromDate)
        .arg(info.deviceNumber)
        .arg(info.programmedCams);
}

}  // namespace

quint64 checkConnectedDevice(QWidget* context, DeviceSession* session, Workspace* workspace,
                             DeviceCheckDone done) {
    QPointer<QWidget> parent(context);
    QPointer<DeviceSession> owner(session);
    session->setDeviceChecked(false);
    return runOnCamCon<Answer>(
        session, context,
        QCoreApplication::translate("cambench::DeviceCheck", "Check which device answers"),
        [](comm::CamConDevice& device, comm::JobContext&) -> Result<Answer> {
            Result<DeviceInfo> identity = device.readInfo();
            if (!identity) return identity.error();
            Answer answer;
            answer.identity = identity.value();
            answer.users = device.has(comm::CamConCapability::Users);
            answer.plc = device.has(comm::CamConCapability::PlcNetworks);
            return answer;
        },
        [parent, owner, workspace, done](Result<Answer> result) {
            if (!result) {
                if (done) done(Status(result.error()), false);
                return;
            }
            const Answer& answer = result.value();
            const std::optional<DeviceInfo> before = workspace->copiesFrom();
            const bool other = !workspace->copiesAreFrom(answer.identity);
            if (other && before) {
                workspace->forgetDeviceCopies(
                    QCoreApplication::translate(
                        "cambench::DeviceCheck",
                        "Another device answers (%1) than the one the values shown as on the "
                        "device were read from (%2). Nothing read from that one is shown as this "
                        "device's any more: the start pages are read again, the rest says \"not "
                        "read\" until Read everything or Compare. Your edits are kept and count "
                        "as not written.")
                        .arg(identityText(answer.identity), identityText(*before)));
            }
            if (!answer.users) workspace->forgetDeviceUsers();
            if (!answer.plc) workspace->forgetDevicePlcNetworks();
            Project project;
            project.device = answer.identity;
            project.readAt.parts.insert(ProjectPart::Device, QDateTime::currentDateTimeUtc());
            mergeIncoming(*workspace, project, ValueSource::Device, {});
            if (owner) owner->setDeviceChecked(true);
            if (done) done(success(), other && before);
        },
        comm::JobPriority::User);
}

}  // namespace cambench
