#pragma once

#include "write_report.h"

#include <QDialog>

class QLabel;
class QPushButton;
class QTreeWidget;

namespace cambench {

class SectionPage;

// "Compare with device": every edited item that differs from the device,
// grouped by section; writes all of them or only the checked ones and
// reports what was written, unchanged and failed.
class CompareDialog : public QDialog {
    Q_OBJECT
public:
    CompareDialog(const QList<SectionPage*>& pages, QWidget* parent = nullptr);

    void refresh();
    int differenceCount() const;
    // Checks exactly the items whose key is in `keys` (all when empty).
    void checkOnly(const QStringList& keys);
    void writeChecked();
    void writeAll();
    QTreeWidget* tree() const { return m_tree; }
    QString reportText() const;

Q_SIGNALS:
    void writeFinished(const cambench::WriteReport& report);

private:
    void write(bool onlyChecked);
    void writeNext(QList<QPair<SectionPage*, QStringList>> queue, WriteReport report);

    QList<SectionPage*> m_pages;
    QTreeWidget* m_tree;
    QLabel* m_report;
    QPushButton* m_writeChecked;
    QPushButton* m_writeAll;
};

}  // namespace cambench
