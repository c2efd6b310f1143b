#include "users_page.h"

#include "access_grid_model.h"
#include "device_reads.h"
#include "ui/device_session.h"
#include "users_model.h"
#include "workspace.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLineEdit>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

namespace cambench {

namespace {
constexpr int kNameLength = 21;
constexpr int kNumberLength = 5;
}  // namespace

UsersPage::UsersPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : CamConSectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_model(new UsersModel(workspace, this)),
      m_access(new AccessGridModel(workspace, this)),
      m_view(new QTableView),
      m_show(new QCheckBox(tr("Show numbers"))),
      m_name(new QLineEdit),
      m_number(new QLineEdit),
      m_allOutputs(new QCheckBox(tr("May change all outputs"))),
      m_editor(new QWidget) {
    auto* add = new QPushButton(tr("Add user"));
    auto* remove = new QPushButton(tr("Remove user"));
    m_show->setToolTip(tr("User numbers are access codes. They stay hidden unless you show them."));
    ReadWriteBar bar([this] { readFromDevice(); }, [this] { writeChanges(); });
    bar.actions = {add, remove};
    bar.right = {m_show};
    QHBoxLayout* buttons = readWriteBar(bar);

    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setSectionResizeMode(UsersModel::NameColumn,
                                                     QHeaderView::ResizeToContents);
    m_view->horizontalHeader()->setSectionResizeMode(UsersModel::NumberColumn,
                                                     QHeaderView::ResizeToContents);
    m_view->horizontalHeader()->setSectionResizeMode(UsersModel::RightsColumn,
                                                     QHeaderView::Stretch);

    m_name->setMaxLength(kNameLength);
    m_number->setMaxLength(kNumberLength);
    auto* details = new QGroupBox(tr("User"));
    auto* form = new QFormLayout(details);
    form->addRow(tr("Name:"), m_name);
    form->addRow(tr("User number:"), m_number);
    auto* rightsBox = new QGroupBox(tr("Rights"));
    auto* rightsGrid = new QGridLayout(rightsBox);
    const QList<QPair<quint32, QString>> rights{
        {User::ProgramSelection, tr("Program selection")},
        {User::Programming, tr("Programming")},
        {User::SystemSettings, tr("System settings")},
        {User::DeviceConfiguration, tr("Device configuration")},
        {User::PlcMenu, tr("PLC menu")},
        {User::AllOutputs, tr("All outputs menu")},
        {User::UserMenu, tr("User menu")},
    };
    for (int i = 0; i < rights.size(); ++i) {
        auto* box = new QCheckBox(rights[i].second);
        rightsGrid->addWidget(box, i / 2, i % 2);
        m_rights.append({rights[i].first, box});
        connect(box, &QCheckBox::toggled, this, &UsersPage::editUser);
    }
    auto* accessBox = new QGroupBox(tr("Outputs this user may change"));
    auto* accessLayout = new QVBoxLayout(accessBox);
    auto* grid = new QTableView;
    grid->setModel(m_access);
    grid->horizontalHeader()->hide();
    grid->verticalHeader()->hide();
    grid->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    grid->setShowGrid(false);
    accessLayout->addWidget(m_allOutputs);
    accessLayout->addWidget(grid);

    auto* editorLayout = new QVBoxLayout(m_editor);
    editorLayout->setContentsMargins(0, 0, 0, 0);
    editorLayout->addWidget(details);
    editorLayout->addWidget(rightsBox);
    editorLayout->addWidget(accessBox, 1);

    auto* body = new QHBoxLayout;
    body->addWidget(m_view, 2);
    body->addWidget(m_editor, 3);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(buttons);
    layout->addLayout(body, 1);

    connect(add, &QPushButton::clicked, this, [this] {
        User user;
        user.name = tr("New user");
        user.outputAccess.resize(256);
        selectUser(m_workspace->users().add(user));
    });
    connect(remove, &QPushButton::clicked, this, [this] {
        if (currentUser() >= 0) m_workspace->users().remove(currentUser());
    });
    connect(m_show, &QCheckBox::toggled, this, &UsersPage::setNumbersShown);
    connect(m_view->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            &UsersPage::showUser);
    connect(m_model, &QAbstractItemModel::modelReset, this, &UsersPage::showUser);
    connect(m_name, &QLineEdit::textEdited, this, &UsersPage::editUser);
    connect(m_number, &QLineEdit::textEdited, this, &UsersPage::editUser);
    connect(m_allOutputs, &QCheckBox::toggled, this, &UsersPage::editUser);
    showUser();
}

void UsersPage::setNumbersShown(bool shown) {
    m_show->setChecked(shown);
    m_model->revealNumbers(shown);
    showUser();
}

int UsersPage::currentUser() const {
    const QModelIndex index = m_view->currentIndex();
    return index.isValid() ? index.row() : -1;
}

void UsersPage::selectUser(int index) {
    m_view->selectRow(index);
}

void UsersPage::showUser() {
    const int index = currentUser();
    m_access->setUser(index);
    m_editor->setEnabled(index >= 0);
    m_updating = true;
    const User user = index >= 0 ? m_workspace->users().row(index).user : User();
    m_name->setText(user.name);
    // Hidden numbers are not even in the field (a password field would
    // still tell their length); they can be edited once shown.
    const bool shown = m_model->numbersRevealed();
    m_number->setReadOnly(!shown);
    m_number->setText(shown ? user.number : QString());
    m_number->setPlaceholderText(shown ? QString()
                                       : tr("hidden – check \"Show numbers\" to see or change it"));
    m_allOutputs->setChecked(user.allOutputs);
    for (const auto& [bit, box] : m_rights) box->setChecked(user.rights & bit);
    m_updating = false;
}

void UsersPage::editUser() {
    const int index = currentUser();
    if (m_updating || index < 0) return;
    User user = m_workspace->users().row(index).user;
    user.name = m_name->text();
    if (m_model->numbersRevealed()) user.number = m_number->text();
    user.allOutputs = m_allOutputs->isChecked();
    user.rights = 0;
    for (const auto& [bit, box] : m_rights) {
        if (box->isChecked()) user.rights |= bit;
    }
    m_workspace->users().set(index, user);
}

void UsersPage::readFromDevice() {
    devicereads::readUsers(this, m_session, m_workspace,
                           reportRead(
                               tr("Reading users…"),
                               [this] {
                                   return tr("%n user(s) read.", nullptr,
                                             int(m_workspace->users().device().size()));
                               },
                               tr("Reading users failed: %1")));
}

int UsersPage::itemCount() const {
    return int(m_workspace->users().size() + m_workspace->users().deletedNumbers().size());
}

QList<SectionDifference> UsersPage::differences() const {
    QList<SectionDifference> list;
    const UserCopies& users = m_workspace->users();
    const auto described = [this](const User& user) {
        return tr("%1, number %2, rights: %3")
            .arg(user.name, m_model->numbersRevealed() ? user.number : user.maskedNumber(),
                 UsersModel::rightsText(user.rights));
    };
    for (int i = 0; i < users.size(); ++i) {
        if (!users.isChanged(i)) continue;
        const UserCopies::EditedUser edited = users.row(i);
        const std::optional<User> device = users.deviceUser(edited.deviceNumber);
        list.append({WorkspaceItem::user(i), tr("User \"%1\"").arg(edited.user.name),
                     device ? described(*device) : tr("absent"), described(edited.user)});
    }
    for (const QString& number : users.deletedNumbers()) {
        if (const std::optional<User> device = users.deviceUser(number))
            list.append({WorkspaceItem::deletedUser(number), tr("User \"%1\"").arg(device->name),
                         described(*device), tr("deleted")});
    }
    return list;
}

void UsersPage::writeChanges(std::function<void(const WriteResult&)> done) {
    writeDifferences(m_session, m_workspace, std::move(done));
}

}  // namespace cambench
