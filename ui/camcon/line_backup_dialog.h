#pragma once

#include "model/camcon/line_manifest.h"

#include <QDialog>
#include <QMap>

class QCheckBox;
class QGridLayout;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;

namespace cambench {

class DeviceSession;

// Device → Back up all devices on this line: every device of a Multiuser
// line (scanned, or the numbers given) into one folder with a manifest
// (usecases::backupLine), one progress bar per device; goes on past a
// device that fails and says so; can resume a run that was cut.
class LineBackupDialog : public QDialog {
    Q_OBJECT
public:
    explicit LineBackupDialog(DeviceSession* session, QWidget* parent = nullptr);

    void setDirectory(const QString& directory);
    // "0,5,7" or empty (scan the line).
    void setDevices(const QString& devices);
    void start();
    bool isRunning() const { return m_job != 0; }
    // One line per device after the run, and the summary.
    QString reportText() const;
    // The bar of a device (null before the run reached it).
    QProgressBar* deviceBar(int device) const { return m_bars.value(device); }
    int deviceBarCount() const { return int(m_bars.size()); }

Q_SIGNALS:
    void finished(bool allSaved);

private:
    void showDeviceProgress(int device, qint64 done, qint64 total, const QString& text);
    void showManifest(const Result<LineManifest>& manifest);

    DeviceSession* m_session;
    QLineEdit* m_directory;
    QLineEdit* m_devices;
    QCheckBox* m_resume;
    QPushButton* m_start;
    QPushButton* m_cancel;
    QGridLayout* m_barGrid;
    QMap<int, QProgressBar*> m_bars;
    QPlainTextEdit* m_report;
    quint64 m_job = 0;
};

}  // namespace cambench
