#include "backup_wizard.h"
#include "ui/camcon/camcon_jobs.h"

#include "ui/device_session.h"
#include "ui/progress_page.h"
#include "ui/replacement_question.h"
#include "workspace.h"

#include "comm/camcon/usecases/backup_restore.h"
#include "model/camcon/eeprom_image_file.h"

#include <QCheckBox>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace cambench {

namespace {

QString identityText(const DeviceInfo& info) {
    return BackupWizard::tr(
               "EPROM %1, device number %2, %3 outputs, %4 programs, positions %5 … %6")
        .arg(info.epromDate)
        .arg(info.deviceNumber)
        .arg(info.outputs)
        .arg(info.programs)
        .arg(info.minPosition)
        .arg(info.maxPosition);
}

QString stamp() {
    return QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss"));
}

}  // namespace

BackupWizard::BackupWizard(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : QWizard(parent), m_session(session), m_workspace(workspace), m_progress(new ProgressPage) {
    setWindowTitle(tr("Backup and restore"));
    setWizardStyle(QWizard::ClassicStyle);
    setOption(QWizard::NoBackButtonOnLastPage);
    setPage(ChoosePage, createChoosePage());
    setPage(CheckPage, createCheckPage());
    m_progress->setCommitPage(false);
    setPage(RunPage, m_progress);
    connect(&m_session->worker(), &comm::JobRunner::jobProgress, this,
            [this](quint64 id, qint64 done, qint64 total, const QString&) {
                if (id == m_job) m_progress->setProgress(done, total);
            });
    resize(720, 480);
}

QWizardPage* BackupWizard::createChoosePage() {
    auto* page = new QWizardPage;
    page->setTitle(tr("Backup or restore"));
    page->setSubTitle(
        tr("A backup copies the device's whole EEPROM into a file. A restore erases "
           "the device and writes such a file back. The file holds the users' "
           "access codes: keep it where only you can read it."));
    m_backup = new QRadioButton(tr("Back up the device into a file"));
    m_restore = new QRadioButton(tr("Restore the device from a file"));
    m_backup->setChecked(true);
    m_path = new QLineEdit;
    m_path->setText(QDir::home().filePath(QStringLiteral("camcon-backup-%1.json").arg(stamp())));
    auto* browse = new QPushButton(tr("Browse…"));
    auto* row = new QHBoxLayout;
    row->addWidget(m_path, 1);
    row->addWidget(browse);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(m_backup);
    layout->addWidget(m_restore);
    layout->addSpacing(12);
    layout->addWidget(new QLabel(tr("File:")));
    layout->addLayout(row);
    layout->addStretch();
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString filter = tr("EEPROM images (*.json)");
        const QString path =
            mode() == Mode::Backup
                ? QFileDialog::getSaveFileName(this, tr("Backup file"), m_path->text(), filter)
                : QFileDialog::getOpenFileName(this, tr("Image to restore"), m_path->text(),
                                               filter);
        if (!path.isEmpty()) m_path->setText(path);
    });
    return page;
}

QWizardPage* BackupWizard::createCheckPage() {
    auto* page = new QWizardPage;
    page->setTitle(tr("Check the image"));
    page->setSubTitle(
        tr("The restore erases the device. Before that, CamBench saves what the device "
           "holds now into a safety backup."));
    m_check = new QLabel;
    m_check->setWordWrap(true);
    m_check->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_safetyPath = new QLineEdit;
    auto* form = new QFormLayout;
    form->addRow(tr("Safety backup:"), m_safetyPath);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(m_check);
    layout->addLayout(form);
    layout->addStretch();
    return page;
}

void BackupWizard::setMode(Mode mode) {
    (mode == Mode::Backup ? m_backup : m_restore)->setChecked(true);
}
void BackupWizard::setPath(const QString& path) {
    m_path->setText(path);
}
void BackupWizard::setSafetyBackupPath(const QString& path) {
    m_safetyPath->setText(path);
}
BackupWizard::Mode BackupWizard::mode() const {
    return m_backup->isChecked() ? Mode::Backup : Mode::Restore;
}
QString BackupWizard::checkText() const {
    return m_check->text();
}

int BackupWizard::nextId() const {
    switch (currentId()) {
        case ChoosePage:
            return mode() == Mode::Backup ? RunPage : CheckPage;
        case CheckPage:
            return RunPage;
        default:
            return -1;
    }
}

bool BackupWizard::validateCurrentPage() {
    if (currentId() == ChoosePage) {
        if (m_path->text().trimmed().isEmpty()) {
            QMessageBox::warning(this, windowTitle(), tr("Choose a file first."));
            return false;
        }
        if (!m_session->isOnline()) {
            QMessageBox::warning(this, windowTitle(), tr("Connect to the device first."));
            return false;
        }
        if (mode() == Mode::Restore) {
            // The model's loader checks format, hash and every block.
            Result<EepromImage> image = loadEepromImage(m_path->text());
            if (!image) {
                QMessageBox::warning(
                    this, windowTitle(),
                    tr("This file cannot be restored: %1").arg(image.error().message));
                return false;
            }
            m_image = image.value();
        }
    }
    if (currentId() == CheckPage) {
        // Another device than the image's: only as its replacement, which
        // the person says with both identities in front of them; the restore
        // then goes only to exactly this device.
        m_consent = {};
        if (!m_mismatch.isEmpty()) {
            const DeviceIdentity device = camConIdentity(m_workspace->info());
            if (!acceptsReplacement(this, windowTitle(), m_path->text(),
                                    camConIdentity(m_image->device), device))
                return false;
            m_consent = ReplacementConsent::of(device);
        }
        if (m_safetyPath->text().trimmed().isEmpty()) {
            QMessageBox::warning(this, windowTitle(), tr("Choose where the safety backup goes."));
            return false;
        }
        // Its own question, also for the device the image came from: the
        // next step erases it.
        QMessageBox confirm(
            QMessageBox::Warning, windowTitle(),
            tr("This erases the device (%1) and writes the image %2 into it. Outputs "
               "may switch while the device restarts.\n\nErase and restore now?")
                .arg(identityText(m_workspace->info()), m_path->text()),
            QMessageBox::NoButton, this);
        QPushButton* erase =
            confirm.addButton(tr("Erase and restore"), QMessageBox::DestructiveRole);
        QPushButton* cancel = confirm.addButton(QMessageBox::Cancel);
        confirm.setDefaultButton(cancel);
        confirm.exec();
        if (confirm.clickedButton() != erase) return false;
    }
    return true;
}

void BackupWizard::initializePage(int id) {
    if (id == CheckPage && m_image) {
        const DeviceInfo& device = m_workspace->info();
        m_mismatch = identityMismatch(m_image->device, device);
        QString text =
            tr("Image: %1\nTaken %2 with %3, %n block(s), %4 bytes.", nullptr,
               int(m_image->blocks.size()))
                .arg(identityText(m_image->device),
                     QLocale().toString(m_image->taken.toLocalTime(), QLocale::ShortFormat),
                     m_image->toolVersion)
                .arg(m_image->totalBytes());
        text += QLatin1Char('\n') + tr("Device: %1").arg(identityText(device));
        if (m_mismatch.isEmpty()) {
            text += QLatin1String("\n\n") + tr("The image matches this device.");
        } else {
            text += QLatin1String("\n\n") + tr("The image does NOT match this device:") +
                    QLatin1Char('\n') + m_mismatch.join(QLatin1Char('\n'));
        }
        m_check->setText(text);
        if (m_safetyPath->text().isEmpty()) {
            // The same name the command line gives it: next to the image, with the time.
            m_safetyPath->setText(
                usecases::safetyBackupPath(m_path->text(), QDateTime::currentDateTimeUtc()));
        }
    }
    if (id == RunPage) {
        m_progress->setTitle(mode() == Mode::Backup ? tr("Backup") : tr("Restore"));
        if (mode() == Mode::Backup) {
            runBackup();
        } else {
            runRestore();
        }
    }
    QWizard::initializePage(id);
}

quint64 BackupWizard::track(quint64 job) {
    m_job = job;
    return job;
}

void BackupWizard::runBackup() {
    const QString path = m_path->text();
    // The device does not say how much its EEPROM holds: bytes and the
    // measured rate, no time left that would be a guess.
    m_progress->start(tr("Reading the EEPROM of the device into %1…").arg(path),
                      ProgressPage::Total::UpperBound);
    track(runOnCamCon<EepromImage>(
        m_session, this, tr("Backup"),
        [path](comm::CamConDevice& device, comm::JobContext& job) {
            return usecases::backupToFile(device, path, usecases::UseCaseProgress::of(job));
        },
        [this, path](Result<EepromImage> image) {
            if (!image) {
                finishWork(false,
                           tr("Backup failed, no file was written: %1").arg(image.error().message));
                return;
            }
            finishWork(true,
                       tr("Backup complete: %n block(s), %1 bytes written to %2. Nothing failed.",
                          nullptr, int(image->blocks.size()))
                           .arg(image->totalBytes())
                           .arg(path));
        }));
}

void BackupWizard::runRestore() {
    const QString imagePath = m_path->text();
    const EepromImage image = *m_image;
    usecases::RestoreOptions options;
    options.replacement = m_consent;
    options.safetyBackupPath = m_safetyPath->text();
    // Step 1 (the safety backup) has no known size: no time left is given.
    m_progress->start(
        tr("Step 1 of 2: saving what the device holds now into %1; step 2: erasing the "
           "device and writing %n block(s).",
           nullptr, int(image.blocks.size()))
            .arg(options.safetyBackupPath),
        ProgressPage::Total::UpperBound);
    track(runOnCamCon<usecases::RestoreReport>(
        m_session, this, tr("Restore"),
        [image, imagePath, options](comm::CamConDevice& device,
                                    comm::JobContext& job) -> Result<usecases::RestoreReport> {
            return usecases::restoreImage(device, image, imagePath, options,
                                          usecases::UseCaseProgress::of(job));
        },
        [this](Result<usecases::RestoreReport> result) {
            const usecases::RestoreReport& report = result.value();
            switch (report.state) {
                case usecases::RestoredState::Restored:
                    Q_EMIT restored();
                    finishWork(
                        true,
                        tr("Restore complete: %n block(s) written, 0 failed. The safety backup of "
                           "the previous content is %1.",
                           nullptr, report.blocks)
                                .arg(report.safetyBackupPath) +
                            (report.linkNote.isEmpty() ? QString()
                                                       : QLatin1Char(' ') + report.linkNote));
                    return;
                case usecases::RestoredState::Unchanged:
                    finishWork(false, tr("Restore NOT done, the device is unchanged: %1")
                                          .arg(report.error.message));
                    return;
                case usecases::RestoredState::ErasedOrPartial:
                    // Whatever the device holds now, the workspace's copy is not it.
                    Q_EMIT restored();
                    finishWork(false, tr("Restore FAILED: %1").arg(report.error.message));
                    return;
            }
        }));
}

void BackupWizard::finishWork(bool ok, const QString& report) {
    m_job = 0;
    m_progress->finish(ok, report);
}

void BackupWizard::reject() {
    if (m_progress->isRunning()) {
        const bool restoring = mode() == Mode::Restore;
        const auto answer = QMessageBox::question(
            this, windowTitle(),
            restoring
                ? tr("Cancel the restore? If the device is already being written, it stays ERASED "
                     "until you restore an image.")
                : tr("Cancel the backup? No file will be written."));
        if (answer != QMessageBox::Yes) return;
        m_session->worker().cancel(m_job);
        return;  // the job ends with Cancelled and the report says what happened
    }
    QWizard::reject();
}

}  // namespace cambench
