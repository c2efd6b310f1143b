#include "page_write_report.h"

#include <QCoreApplication>
#include <QMessageBox>

namespace cambench {

void PageWriteReport::addFailure(const QString& item, const Error& error) {
    ++failed;
    failures << QCoreApplication::translate("PageWriteReport", "%1: %2").arg(item, error.message);
}

void PageWriteReport::addRefusal(const QString& item, const QString& reason) {
    ++failed;
    refusals << QCoreApplication::translate("PageWriteReport", "%1: %2").arg(item, reason);
}

void PageWriteReport::add(const PageItemOutcomes& outcomes) {
    for (const PageItemOutcome& outcome : outcomes) {
        if (outcome.error.kind == ErrorKind::None) {
            ++written;
        } else {
            addFailure(outcome.item, outcome.error);
        }
    }
}

QString PageWriteReport::summary() const {
    return QCoreApplication::translate("PageWriteReport", "%1 written, %2 unchanged, %3 failed")
        .arg(written)
        .arg(unchanged)
        .arg(failed);
}

QString PageWriteReport::details() const {
    QString text = summary();
    if (!refusals.isEmpty()) {
        text += QLatin1Char('\n') +
                QCoreApplication::translate("PageWriteReport",
                                            "Not sent, as the device would refuse it (the "
                                            "device is untouched; correct the marked values):") +
                QLatin1Char('\n') + refusals.join(QLatin1Char('\n'));
    }
    if (!failures.isEmpty()) {
        text +=
            QLatin1Char('\n') +
            QCoreApplication::translate(
                "PageWriteReport",
                "Not written, or not confirmed by the device (a reply may have been lost). Your "
                "edits stay on the page; Read from device shows what the device holds:") +
            QLatin1Char('\n') + failures.join(QLatin1Char('\n'));
    }
    return text;
}

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
