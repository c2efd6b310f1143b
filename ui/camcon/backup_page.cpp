#include "backup_page.h"

#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace cambench {

BackupPage::BackupPage(QWidget* parent) : CamConSectionPage(parent) {
    auto* text = new QLabel(
        tr("<h3>Backup and restore</h3>"
           "<p>A <b>backup</b> copies the whole EEPROM of the device (cam programs, dead times, "
           "settings, users, PLC) block by block into a file.</p>"
           "<p>A <b>restore</b> erases the device and writes such a file back. CamBench checks the "
           "file first, restores it only to the device it was taken from (or to its replacement "
           "when you say so), and saves "
           "what the device holds now into a safety backup before it erases anything.</p>"
           "<p>If a restore is interrupted, the device stays erased and does not run until an "
           "image is restored completely: keep the safety backup.</p>"));
    text->setWordWrap(true);
    text->setTextFormat(Qt::RichText);
    auto* open = new QPushButton(tr("Backup or restore…"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(text);
    layout->addWidget(open, 0, Qt::AlignLeft);
    layout->addStretch();
    connect(open, &QPushButton::clicked, this, &BackupPage::wizardRequested);
}

}  // namespace cambench
