#pragma once

#include "comm/usecases/item_outcome.h"

#include <QDialog>
#include <QMessageBox>

class QDialogButtonBox;
class QLabel;
class QPlainTextEdit;

namespace cambench {

// A message with a short summary above and any number of detail lines in
// a scrolling box below: never taller than the screen, its OK button always
// on it (a QMessageBox grows with its text; 96 failures made one 2,774 px).
class ReportDialog : public QDialog {
    Q_OBJECT
public:
    ReportDialog(QMessageBox::Icon icon, const QString& title, const QString& summary,
                 const QString& details, QWidget* parent = nullptr);

    QString summary() const;
    QString details() const;
    QDialogButtonBox* buttons() const { return m_buttons; }

    // Modal; returns when the user closed it.
    static void present(QWidget* parent, QMessageBox::Icon icon, const QString& title,
                        const QString& summary, const QString& details = {});
    // A write's report, whatever the family: the summary, and every item
    // that was not unchanged with its outcome; a warning unless complete.
    static void presentTally(QWidget* parent, const QString& title,
                             const usecases::OutcomeTally& tally);

private:
    QLabel* m_summary;
    QPlainTextEdit* m_details;
    QDialogButtonBox* m_buttons;
};

}  // namespace cambench
