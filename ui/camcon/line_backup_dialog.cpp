#include "line_backup_dialog.h"
#include "ui/camcon/camcon_jobs.h"

#include "ui/device_session.h"

#include "comm/camcon/usecases/line_backup.h"
#include "comm/device/protocol_registry.h"

#include <QCheckBox>
#include <QDateTime>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

namespace cambench {

LineBackupDialog::LineBackupDialog(DeviceSession* session, QWidget* parent)
    : QDialog(parent),
      m_session(session),
      m_directory(new QLineEdit),
      m_devices(new QLineEdit),
      m_resume(new QCheckBox(tr("Resume: skip devices already saved and verified in this folder"))),
      m_start(new QPushButton(tr("Back up"))),
      m_cancel(new QPushButton(tr("Cancel"))),
      m_barGrid(new QGridLayout),
      m_report(new QPlainTextEdit) {
    setWindowTitle(tr("Back up all devices on this line"));
    m_directory->setText(QDir::home().filePath(
        QStringLiteral("line-backup-%1")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")))));
    m_devices->setPlaceholderText(tr("empty: scan the line for devices 0 … 63"));
    auto* browse = new QPushButton(tr("Browse…"));
    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(m_directory, 1);
    folderRow->addWidget(browse);
    auto* form = new QFormLayout;
    form->addRow(tr("Folder:"), folderRow);
    form->addRow(tr("Devices:"), m_devices);
    form->addRow(QString(), m_resume);

    auto* bars = new QWidget;
    auto* barsLayout = new QVBoxLayout(bars);
    barsLayout->addLayout(m_barGrid);
    barsLayout->addStretch();
    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setWidget(bars);
    m_report->setReadOnly(true);
    m_report->setMaximumHeight(fontMetrics().lineSpacing() * 8);

    auto* intro =
        new QLabel(tr("Each device of the line is backed up into its own image in the folder, "
                      "with a manifest of what was saved. A device that fails is noted and "
                      "the others are still backed up."));
    intro->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    buttons->addButton(m_start, QDialogButtonBox::ActionRole);
    buttons->addButton(m_cancel, QDialogButtonBox::ActionRole);
    m_cancel->setEnabled(false);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(scroll, 1);
    layout->addWidget(m_report);
    layout->addWidget(buttons);

    connect(browse, &QPushButton::clicked, this, [this] {
        const QString directory =
            QFileDialog::getExistingDirectory(this, windowTitle(), m_directory->text());
        if (!directory.isEmpty()) m_directory->setText(directory);
    });
    connect(m_start, &QPushButton::clicked, this, &LineBackupDialog::start);
    connect(m_cancel, &QPushButton::clicked, this, [this] {
        if (m_job != 0) m_session->worker().cancel(m_job);
    });
    connect(buttons, &QDialogButtonBox::rejected, this, [this] {
        if (m_job == 0) reject();
    });
    resize(640, 520);
}

void LineBackupDialog::setDirectory(const QString& directory) {
    m_directory->setText(directory);
}
void LineBackupDialog::setDevices(const QString& devices) {
    m_devices->setText(devices);
}
QString LineBackupDialog::reportText() const {
    return m_report->toPlainText();
}

void LineBackupDialog::start() {
    if (m_job != 0) return;
    usecases::LineBackupOptions options;
    options.directory = m_directory->text().trimmed();
    options.resume = m_resume->isChecked();
    for (const QString& part : m_devices->text().split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        bool ok = false;
        const int device = part.trimmed().toInt(&ok);
        if (!ok || device < 0 || device > 63 || options.devices.contains(device)) {
            m_report->setPlainText(
                tr("\"%1\" is not a device number 0 … 63 (or given twice); write the "
                   "numbers with commas, e.g. 0, 5, 7.")
                    .arg(part.trimmed()));
            return;
        }
        options.devices << device;
    }
    options.lineDescription =
        tr("%1, %2, %3 baud")
            .arg(m_session->connection().port, m_session->protocol().protocolId())
            .arg(m_session->connection().serial.baud);
    while (QLayoutItem* item = m_barGrid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    m_bars.clear();
    // Known devices get their bar now; scanned ones as the scan finds them.
    for (int device : options.devices) showDeviceProgress(device, 0, 1, tr("waiting"));
    m_report->setPlainText(options.devices.isEmpty() ? tr("Scanning the line…")
                                                     : tr("Backing up…"));
    m_start->setEnabled(false);
    m_cancel->setEnabled(true);
    const int addressed = m_session->protocol().device();
    QPointer<LineBackupDialog> self(this);
    m_job = runOnCamCon<LineManifest>(
        m_session, this, tr("Back up the line"),
        [options, self](comm::CamConDevice& device, comm::JobContext& job) {
            // Per device, on the worker thread: hand it to the dialog's thread.
            const usecases::DeviceProgressFn perDevice = [self](int number, qint64 done,
                                                                qint64 total, const QString& text) {
                QMetaObject::invokeMethod(
                    self,
                    [self, number, done, total, text] {
                        if (self) self->showDeviceProgress(number, done, total, text);
                    },
                    Qt::QueuedConnection);
            };
            return usecases::backupLine(device, options, usecases::UseCaseProgress::of(job),
                                        perDevice);
        },
        [this, addressed](Result<LineManifest> manifest) {
            m_job = 0;
            // The use case leaves the line addressed to the last device it reached.
            if (addressed >= 0) m_session->setDevice(addressed);
            showManifest(manifest);
        });
}

void LineBackupDialog::showDeviceProgress(int device, qint64 done, qint64 total,
                                          const QString& text) {
    QProgressBar* bar = m_bars.value(device);
    if (!bar) {
        bar = new QProgressBar;
        bar->setObjectName(QStringLiteral("device%1").arg(device));
        const int row = m_barGrid->rowCount();
        m_barGrid->addWidget(new QLabel(tr("Device %1").arg(device)), row, 0);
        m_barGrid->addWidget(bar, row, 1);
        m_bars.insert(device, bar);
    }
    if (total > 0) {
        bar->setRange(0, 1000);
        bar->setValue(int(done * 1000 / total));
    }
    bar->setFormat(text.isEmpty() ? QStringLiteral("%p %") : text + QStringLiteral(" – %p %"));
}

void LineBackupDialog::showManifest(const Result<LineManifest>& manifest) {
    m_start->setEnabled(true);
    m_cancel->setEnabled(false);
    if (!manifest) {
        m_report->setPlainText(tr("Nothing was backed up: %1").arg(manifest.error().message));
        Q_EMIT finished(false);
        return;
    }
    QStringList lines;
    int saved = 0;
    for (const LineManifestEntry& entry : manifest->devices) {
        const bool ok = entry.outcome == LineManifestEntry::Outcome::Saved;
        saved += ok ? 1 : 0;
        if (!m_bars.contains(entry.device)) showDeviceProgress(entry.device, 0, 1, {});
        QProgressBar* bar = m_bars.value(entry.device);
        bar->setFormat(ok ? tr("saved") : tr("FAILED"));
        bar->setValue(bar->maximum());
        // A failed device must stand out among the saved ones: a red bar.
        if (!ok)
            bar->setStyleSheet(
                QStringLiteral("QProgressBar { color: white; text-align: center; }"
                               " QProgressBar::chunk { background-color: #b03a2e; }"));
        lines << (ok ? tr("Device %1: saved to %2.").arg(entry.device).arg(entry.file)
                     : tr("Device %1: NOT saved: %2").arg(entry.device).arg(entry.message));
    }
    const int failed = int(manifest->devices.size()) - saved;
    lines.prepend(
        failed == 0 ? tr("All %n device(s) saved into %1.", nullptr, saved).arg(m_directory->text())
                    : tr("%1 of %2 devices saved; %3 NOT saved (see below). The manifest in %4 "
                         "says the same.")
                          .arg(saved)
                          .arg(manifest->devices.size())
                          .arg(failed)
                          .arg(m_directory->text()));
    m_report->setPlainText(lines.join(QLatin1Char('\n')));
    Q_EMIT finished(failed == 0 && saved > 0);
}

}  // namespace cambench
