#pragma once

#include "model/camcon/eeprom_image.h"
#include "model/result.h"

#include <QWizard>

#include <optional>

class QLabel;
class QLineEdit;
class QRadioButton;

namespace cambench {

class DeviceSession;
class ProgressPage;
class Workspace;

// Backup and restore of the whole EEPROM, following the safety rules: the
// image is checked by the model's loader, a different device (another
// identity, camConIdentity) only as the replacement of the image's, which
// the person says in a question showing both (acceptsReplacement), a safety
// backup of the device is taken first, and
// the report says plainly when a failed restore left the device erased.
class BackupWizard : public QWizard {
    Q_OBJECT
public:
    enum Page { ChoosePage, CheckPage, RunPage };
    enum class Mode { Backup, Restore };

    BackupWizard(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    void setMode(Mode mode);
    void setPath(const QString& path);
    void setSafetyBackupPath(const QString& path);
    Mode mode() const;
    ProgressPage* progressPage() const { return m_progress; }
    QString checkText() const;

    int nextId() const override;
    bool validateCurrentPage() override;
    void initializePage(int id) override;
    void reject() override;

Q_SIGNALS:
    // The device's content was replaced: everything read before is stale.
    void restored();

private:
    QWizardPage* createChoosePage();
    QWizardPage* createCheckPage();
    void runBackup();
    void runRestore();
    void finishWork(bool ok, const QString& report);
    quint64 track(quint64 job);

    DeviceSession* m_session;
    Workspace* m_workspace;
    QRadioButton* m_backup;
    QRadioButton* m_restore;
    QLineEdit* m_path;
    QLabel* m_check;
    QLineEdit* m_safetyPath;
    ProgressPage* m_progress;
    std::optional<EepromImage> m_image;
    QStringList m_mismatch;
    ReplacementConsent m_consent;  // the replacement the person accepted
    quint64 m_job = 0;
};

}  // namespace cambench
