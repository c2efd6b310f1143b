#pragma once

#include "compax3_page.h"

#include "model/compax3/compax3_parameter_file.h"

class QCheckBox;
class QLabel;
class QTableWidget;

namespace cambench {

namespace usecases {
struct Compax3RestoreOptions;
}

class Compax3Gui;

// Parameters, the "replace a broken drive" workflow: save the drive's
// parameters to a file, compare a file with the drive (the differences in
// a table, each with a box to write it), write all or the selected
// differences with written/unchanged/failed per object; to another drive
// than the file's only when the person accepts it as the replacement (the
// question shows both); a file of another drive type only when "Write to
// another drive type" is ticked; the sets
// stored in flash afterwards when asked.
class Compax3ParametersPage : public Compax3Page {
    Q_OBJECT
public:
    Compax3ParametersPage(DeviceSession* session, Compax3Gui* gui, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Parameters"); }

    void saveToFile(const QString& path);
    void compareWith(const QString& path);
    // `selectedOnly`: the ticked rows of the comparison.
    void writeFile(bool selectedOnly);
    QTableWidget* differences() const { return m_table; }

protected:
    // Another drive (or none): an earlier comparison's file header, result
    // and differences were the drive before's.
    void factsChanged() override;

private:
    // writeFile once the drive is known to be the file's or its accepted
    // replacement.
    void writeChecked(bool selectedOnly, const usecases::Compax3RestoreOptions& options);

    Compax3Gui* m_gui;
    QLabel* m_file;
    QTableWidget* m_table;
    QCheckBox* m_force;
    QCheckBox* m_store;
    std::optional<Compax3ParameterSet> m_set;
    QString m_path;
};

}  // namespace cambench
