#pragma once

#include "ui/camcon/camcon_section_page.h"

#include <QList>

class QCheckBox;
class QLineEdit;
class QTableView;

namespace cambench {

class AccessGridModel;
class DeviceSession;
class UsersModel;
class Workspace;

// Key assignment: the users, their rights and per-output access. User
// numbers are masked everywhere until "Show numbers" is checked.
class UsersPage : public CamConSectionPage {
    Q_OBJECT
public:
    UsersPage(DeviceSession* session, Workspace* workspace, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Users"); }
    QList<SectionDifference> differences() const override;
    int itemCount() const override;
    void writeChanges(std::function<void(const WriteResult&)> done = {});

    void readFromDevice();
    void setNumbersShown(bool shown);
    void selectUser(int index);
    UsersModel* model() const { return m_model; }
    QTableView* view() const { return m_view; }
    QLineEdit* numberEdit() const { return m_number; }

private:
    void showUser();
    void editUser();
    int currentUser() const;

    DeviceSession* m_session;
    Workspace* m_workspace;
    UsersModel* m_model;
    AccessGridModel* m_access;
    QTableView* m_view;
    QCheckBox* m_show;
    QLineEdit* m_name;
    QLineEdit* m_number;
    QCheckBox* m_allOutputs;
    QList<QPair<quint32, QCheckBox*>> m_rights;
    QWidget* m_editor;
    bool m_updating = false;
};

}  // namespace cambench
