#pragma once

#include "device_writer.h"

#include <QDialog>

class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QTreeWidget;

namespace cambench {

class DeviceSession;
class CamConSectionPage;
class Workspace;

// "Compare with device": reads the device first (progress, cancel), then
// lists every edited item that differs from what the device holds now,
// grouped by section, and says when those device values were read. Items
// the device changed by itself since the last read are listed too. Writes
// all items or only the checked ones, and reports per item.
class CompareDialog : public QDialog {
    Q_OBJECT
public:
    CompareDialog(DeviceSession* session, Workspace* workspace,
                  const QList<CamConSectionPage*>& pages, QWidget* parent = nullptr);

    // Reads the device again (offline: shows the last device copy, saying so).
    void refresh();
    bool isReading() const { return m_readJob != 0; }
    void cancelReading();
    int differenceCount() const;
    // Checks exactly the items in `items` (all when empty).
    void checkOnly(const QList<WorkspaceItem>& items);
    void writeChecked();
    void writeAll();
    QTreeWidget* tree() const { return m_tree; }
    QString reportText() const;
    // "Device values read at 12:03:04" and what the read said.
    QString sourceText() const;

Q_SIGNALS:
    void writeFinished(const cambench::WriteResult& result);
    // The device's values arrived (or could not be read); the list is current.
    void compared();

private:
    void showDifferences();
    QList<WorkspaceItem> uncheckedItems() const;
    // Said where the edits are a copy of another device (empty: they are not).
    QString copyNote() const;
    void write(bool onlyChecked);
    void setBusy(bool busy);

    DeviceSession* m_session;
    Workspace* m_workspace;
    QList<CamConSectionPage*> m_pages;
    QLabel* m_source;
    QProgressBar* m_progress;
    QPushButton* m_cancel;
    QTreeWidget* m_tree;
    QPlainTextEdit* m_report;
    QPushButton* m_writeChecked;
    QPushButton* m_writeAll;
    QPushButton* m_refresh;
    quint64 m_readJob = 0;
    QStringList m_deviceChanges;
};

}  // namespace cambench
