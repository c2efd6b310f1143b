#include "check_report_dialog.h"

#include "device_session.h"
#include "report_dialog.h"

#include "model/atomic_file.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QJsonDocument>
#include <QPushButton>

namespace cambench {

void presentCheckReport(QWidget* parent, const usecases::CheckReport& report) {
    using usecases::CheckVerdict;
    const QString summary =
        QCoreApplication::translate(
            "cambench::CheckReportDialog",
            "%1 held, %2 refuted, %3 could not tell (%4 requests sent, all reading). Save the "
            "report and send it back, so that our tables can be corrected.")
            .arg(report.count(CheckVerdict::Held))
            .arg(report.count(CheckVerdict::Refuted))
            .arg(report.count(CheckVerdict::CouldNotTell))
            .arg(report.requestsSent);
    ReportDialog dialog(
        report.anyRefuted() ? QMessageBox::Warning : QMessageBox::Information,
        QCoreApplication::translate("cambench::CheckReportDialog", "Check this device"), summary,
        usecases::checkReportText(report), parent);
    QPushButton* save = dialog.buttons()->addButton(
        QCoreApplication::translate("cambench::CheckReportDialog", "Save…"),
        QDialogButtonBox::ActionRole);
    QObject::connect(save, &QPushButton::clicked, &dialog, [&dialog, &report] {
        const QString path = QFileDialog::getSaveFileName(
            &dialog,
            QCoreApplication::translate("cambench::CheckReportDialog", "Save the check report"),
            QStringLiteral("check-%1.json").arg(report.familyId),
            QCoreApplication::translate("cambench::CheckReportDialog", "Check report (*.json)"));
        if (path.isEmpty()) return;
        const Status written = writeFileAtomically(
            path, QJsonDocument(usecases::checkReportJson(report)).toJson(QJsonDocument::Indented));
        if (!written) {
            ReportDialog::present(
                &dialog, QMessageBox::Critical,
                QCoreApplication::translate("cambench::CheckReportDialog", "Save the check report"),
                written.error().message);
        }
    });
    dialog.exec();
}

void runDeviceCheck(DeviceSession* session, QWidget* parent) {
    session->run<comm::DeviceConnection, usecases::CheckReport>(
        parent, QCoreApplication::translate("cambench::CheckReportDialog", "Check this device"),
        [](comm::DeviceConnection& device, comm::JobContext& job) {
            return usecases::checkDevice(device, usecases::UseCaseProgress::of(job));
        },
        [parent](Result<usecases::CheckReport> report) {
            if (!report) {
                ReportDialog::present(
                    parent, QMessageBox::Critical,
                    QCoreApplication::translate("cambench::CheckReportDialog", "Check this device"),
                    QCoreApplication::translate("cambench::CheckReportDialog",
                                                "The check did not run to its end: %1")
                        .arg(report.error().message));
                return;
            }
            presentCheckReport(parent, *report);
        });
}

}  // namespace cambench
