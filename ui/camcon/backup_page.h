#pragma once

#include "ui/camcon/camcon_section_page.h"

namespace cambench {

// The Backup section: what backup and restore do, and the way into the wizard.
class BackupPage : public CamConSectionPage {
    Q_OBJECT
public:
    explicit BackupPage(QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Backup"); }

Q_SIGNALS:
    void wizardRequested();
};

}  // namespace cambench
