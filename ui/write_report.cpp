#include "write_report.h"

#include <QCoreApplication>

namespace cambench {

void WriteReport::addFailure(const QString& item, const Error& error) {
    ++failed;
    failures << QCoreApplication::translate("WriteReport", "%1: %2").arg(item, error.message);
}

void WriteReport::merge(const WriteReport& other) {
    written += other.written;
    unchanged += other.unchanged;
    failed += other.failed;
    failures += other.failures;
}

void WriteReport::add(const ItemOutcomes& outcomes) {
    for (const ItemOutcome& outcome : outcomes) {
        if (outcome.error.kind == ErrorKind::None) {
            addWritten();
        } else {
            addFailure(outcome.item, outcome.error);
        }
    }
}

QString WriteReport::summary() const {
    return QCoreApplication::translate("WriteReport", "%1 written, %2 unchanged, %3 failed")
        .arg(written)
        .arg(unchanged)
        .arg(failed);
}

QString WriteReport::details() const {
    QString text = summary();
    if (!failures.isEmpty()) {
        text += QLatin1Char('\n') +
                QCoreApplication::translate("WriteReport",
                                            "Not written (the device keeps its old values):") +
                QLatin1Char('\n') + failures.join(QLatin1Char('\n'));
    }
    return text;
}

}  // namespace cambench
