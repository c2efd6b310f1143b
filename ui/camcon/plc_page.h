#pragma once

#include "ui/camcon/camcon_section_page.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QSpinBox;
class QTableView;

namespace cambench {

class DeviceSession;
class PlcMatrixModel;
class Workspace;

// The PLC logic matrix: networks by area (O, P, M, X) and number, each with
// its value, reset field and 5 x 6 symbols.
class PlcPage : public CamConSectionPage {
    Q_OBJECT
public:
    PlcPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("PLC"); }
    QList<SectionDifference> differences() const override;
    int itemCount() const override;
    void writeChanges(std::function<void(const WriteResult&)> done = {});

    void showNetwork(int area, int number);  // number 0-based
    void readNetwork();
    PlcMatrixModel* model() const { return m_model; }
    // Why the last entry in the matrix was not taken (empty: it was).
    QString refusalText() const;

    static QString networkName(int area, int number);

private:
    void showFields();
    void fillList();
    void editFields();

    DeviceSession* m_session;
    Workspace* m_workspace;
    PlcMatrixModel* m_model;
    QComboBox* m_area;
    QSpinBox* m_number;
    QSpinBox* m_value;
    QLineEdit* m_reset;
    QTableView* m_matrix;
    QListWidget* m_networks;
    QLabel* m_refusal;
    bool m_updating = false;
};

}  // namespace cambench
