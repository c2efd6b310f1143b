#pragma once

#include "ui/camcon/camcon_section_page.h"

class QLabel;
class QTableView;

namespace cambench {

class DeadTimesModel;
class DeviceSession;
class Workspace;

// Dead times (and names) of the outputs: read, edit, write the changed ones.
class DeadTimesPage : public CamConSectionPage {
    Q_OBJECT
public:
    DeadTimesPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Dead times"); }
    QList<SectionDifference> differences() const override;
    int itemCount() const override;
    void writeChanges(std::function<void(const WriteResult&)> done = {});

    void readFromDevice();
    QTableView* view() const { return m_view; }
    DeadTimesModel* model() const { return m_model; }

private:
    void showLimits();

    DeviceSession* m_session;
    Workspace* m_workspace;
    DeadTimesModel* m_model;
    QTableView* m_view;
    QLabel* m_limits;
};

}  // namespace cambench
