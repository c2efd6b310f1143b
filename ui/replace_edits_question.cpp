#include "replace_edits_question.h"

#include <QCoreApplication>
#include <QMessageBox>

namespace cambench {

bool mayReplaceEdits(QWidget* page, const QString& title, int changes) {
    if (changes == 0) return true;
    return QMessageBox::question(
               page, title,
               QCoreApplication::translate("PageWriteReport",
                                           "%n edited value(s) on this page are not written. "
                                           "Replace them with what the device holds?",
                                           nullptr, changes)) == QMessageBox::Yes;
}

}  // namespace cambench
