#pragma once

#include "mc1_page.h"

class QLabel;
class QSpinBox;
class QTableView;

namespace cambench {

class Mc1WatchModel;

// Variables: a watch table of the controller's variables (ranges or
// single ones, a name of one's own, a CSV name list), their live values,
// and writing a value after a confirmation that names it.
class Mc1VariablesPage : public Mc1Page {
    Q_OBJECT
public:
    Mc1VariablesPage(DeviceSession* session, Mc1WatchModel* model, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Variables"); }
    bool poll() override;
    void markStale() override;

    Mc1WatchModel* model() const { return m_model; }
    QTableView* table() const { return m_table; }
    // Asks (naming `typed`, the value as typed; empty: `value`), then
    // writes `value` to variable `number` and reads it back.
    void writeVariable(int number, qint64 value, const QString& typed = {});
    void importNames(const QString& path);
    // The watch list (numbers, names, last values) to and from a project file.
    void saveList(const QString& path);
    void openList(const QString& path);

protected:
    void freshnessChanged() override;

private:
    void addRange();

    Mc1WatchModel* m_model;
    QTableView* m_table;
    QSpinBox* m_first;
    QSpinBox* m_last;
};

}  // namespace cambench
