#include "device_check.h"
#include "ui/camcon/camcon_jobs.h"

#include "device_change_dialog.h"
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
    bool tableSections = true;
};

// Asks what stays when the person had changed values of the old device;
// without changes the new device's values are taken.
CarryOver askWhatStays(QWidget* parent, const Workspace& workspace, const DeviceInfo& before,
                       const DeviceInfo& now) {
    const QStringList changes = personsChanges(workspace);
    if (changes.isEmpty()) return CarryOver::Nothing;
    DeviceChangeDialog dialog(deviceName(before), deviceName(now), changes, parent);
    dialog.exec();
    return dialog.choice();
}

// The banner while anything of the other device could still be looked for.
// (The new device is named on the line above it; the old one once, so
// that the banner fits whole.)
QString otherDeviceNote(CarryOver carry, const DeviceInfo& before, int carried) {
    QString note = QCoreApplication::translate(
                       "cambench::DeviceCheck",
                       "Another device answers: nothing read from %1 is shown as this one's.")
                       .arg(deviceName(before));
    if (carry == CarryOver::Changes)
        note += QLatin1Char(' ') +
                QCoreApplication::translate("cambench::DeviceCheck",
                                            "Your changes (%1) stay, not written yet.")
                    .arg(carried);
    if (carry == CarryOver::Everything)
        note += QLatin1Char(' ') +
                QCoreApplication::translate("cambench::DeviceCheck",
                                            "A copy of that device's values waits to be written.");
    return note;
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
            answer.tableSections = device.has(comm::CamConCapability::DeadTimeModes);
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
                const CarryOver carry = askWhatStays(parent, *workspace, *before, answer.identity);
                const int changes = workspace->changedCount();
                workspace->forgetDeviceCopies(otherDeviceNote(carry, *before, changes), carry);
            }
            if (!answer.users) workspace->forgetDeviceSection(ProjectPart::Users);
            if (!answer.plc) workspace->forgetDeviceSection(ProjectPart::PlcNetworks);
            // An earlier device's dead-time modes are not this one's (a
            // report of a Cam-BUS device showed a 3964R device's).
            if (!answer.tableSections) workspace->forgetDeviceTableSections();
            Project project;
            project.device = answer.identity;
            project.readAt.parts.insert(ProjectPart::Device, QDateTime::currentDateTimeUtc());
            mergeIncoming(*workspace, project, ValueSource::Device, {});
            if (owner && other && before) owner->noteAnotherDevice();
            if (owner) owner->setDeviceChecked(true);
            if (done) done(success(), other && before);
        },
        comm::JobPriority::User);
}

}  // namespace cambench
