#include "replacement_question.h"

#include "device_session.h"
#include "report_dialog.h"
#include "sentence.h"

#include "comm/device/device_connection.h"

#include <QCoreApplication>
#include <QMessageBox>
#include <QPushButton>
#include <QSet>

namespace cambench {

namespace {

// One line per value: "serial: C3-1 (backup), C3-2 (this device)  ← differs".
QString comparison(const DeviceIdentity& backup, const DeviceIdentity& found) {
    QSet<QString> keys;
    for (const QString& key : backup.values().keys()) keys.insert(key);
    for (const QString& key : found.values().keys()) keys.insert(key);
    QStringList sorted(keys.begin(), keys.end());
    sorted.sort();
    QStringList lines;
    for (const QString& key : sorted) {
        const QString was = backup.values().value(
            key, QCoreApplication::translate("ReplacementQuestion", "not recorded"));
        const QString now =
            found.values().value(key, QCoreApplication::translate("ReplacementQuestion", "none"));
        lines << (was == now
                      ? QCoreApplication::translate("ReplacementQuestion", "%1: %2 (the same)")
                            .arg(key, now)
                      : QCoreApplication::translate("ReplacementQuestion",
                                                    "%1: backup %2, this device %3  ← differs")
                            .arg(key, was, now));
    }
    return lines.join(QLatin1Char('\n'));
}

}  // namespace

bool acceptsReplacement(QWidget* parent, const QString& title, const QString& backupName,
                        const DeviceIdentity& backup, const DeviceIdentity& found) {
    QMessageBox ask(
        QMessageBox::Warning, title,
        backup.known()
            ? QCoreApplication::translate("ReplacementQuestion",
                                          "The device answering is not the one %1 was taken from.")
                  .arg(backupName)
            : QCoreApplication::translate(
                  "ReplacementQuestion",
                  "%1 records no identity of the device it was taken from (an older "
                  "backup): CamBench cannot tell whether the device answering is "
                  "that device.")
                  .arg(backupName),
        QMessageBox::Cancel, parent);
    ask.setObjectName(QStringLiteral("replacementQuestion"));
    // Both identities in full sight, not behind "Show Details".
    ask.setInformativeText(
        QCoreApplication::translate(
            "ReplacementQuestion",
            "%1\n\nRestore it here only if this device replaces the one the backup was taken "
            "from (or, for an older backup, is that device). Nothing has been written yet.")
            .arg(comparison(backup, found)));
    QPushButton* replace = ask.addButton(
        QCoreApplication::translate("ReplacementQuestion", "It replaces that device: restore"),
        QMessageBox::DestructiveRole);
    replace->setObjectName(QStringLiteral("acceptReplacement"));
    ask.setDefaultButton(QMessageBox::Cancel);
    ask.exec();
    return ask.clickedButton() == replace;
}

void askRestoreTarget(DeviceSession* session, QObject* context, QWidget* parent,
                      const QString& title, const QString& backupName, const DeviceIdentity& backup,
                      std::function<void(const ReplacementConsent&)> go,
                      std::function<void(const QString& why)> declined) {
    session->run<comm::DeviceConnection, DeviceIdentity>(
        context, QCoreApplication::translate("ReplacementQuestion", "Check which device answers"),
        [](comm::DeviceConnection& device, comm::JobContext&) { return device.readIdentity(); },
        [parent, title, backupName, backup, go = std::move(go),
         declined = std::move(declined)](Result<DeviceIdentity> found) {
            if (!found) {
                const QString why = QCoreApplication::translate(
                                        "ReplacementQuestion",
                                        "Nothing was written: which device answers could not "
                                        "be read: %1")
                                        .arg(asSentence(found.error().message));
                ReportDialog::present(parent, QMessageBox::Warning, title, why);
                if (declined) declined(why);
                return;
            }
            if (backup.known() && backup == *found) {
                go({});
                return;
            }
            if (acceptsReplacement(parent, title, backupName, backup, *found))
                go(ReplacementConsent::of(*found));
            else if (declined)
                declined(anotherDeviceText(backup, *found));
        });
}

}  // namespace cambench
