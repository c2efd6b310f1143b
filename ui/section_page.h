#pragma once

#include "write_report.h"

#include <QWidget>

#include <functional>

namespace cambench {

// One line of "Compare with device": an item whose edited value differs
// from the device's. `key` identifies it for writeItems().
struct SectionDifference {
    QString key;
    QString item;
    QString device;
    QString edited;
};

// A page of the main window that shows one section of a device. Pages that
// hold data know what came from the device and what was edited, list the
// differences and write a chosen subset of them.
class SectionPage : public QWidget {
    Q_OBJECT
public:
    using QWidget::QWidget;

    virtual QString sectionTitle() const = 0;
    virtual QList<SectionDifference> differences() const { return {}; }
    // Writes the items with these keys; `done` gets the per-item report.
    virtual void writeItems(const QStringList& keys, std::function<void(const WriteReport&)> done) {
        Q_UNUSED(keys);
        done({});
    }
    // Called when the device's identity is known (after connect or reconnect).
    virtual void deviceConnected() {}

Q_SIGNALS:
    void statusMessage(const QString& text);
};

}  // namespace cambench
