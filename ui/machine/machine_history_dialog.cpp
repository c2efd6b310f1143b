#include "machine_history_dialog.h"

#include "machine.h"
#include "machine_history_jobs.h"
#include "machine_unit.h"

#include "model/machine/machine_backup_folder.h"
#include "ui/family_gui.h"
#include "ui/report_pages.h"
#include "ui/window_fit.h"

#include <QDateTime>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace cambench {

namespace {

// The word the table's last column shows for a device without differences.
QString deviceState(const usecases::DeviceChange& change) {
    using Kind = usecases::DeviceChange::Kind;
    switch (change.kind) {
        case Kind::Equal:
            return change.volatileLeftOut == 0
                       ? MachineHistoryDialog::tr("equal")
                       : MachineHistoryDialog::tr("equal (%n change(s) of volatile items left out)",
                                                  nullptr, change.volatileLeftOut);
        case Kind::Added:
            return MachineHistoryDialog::tr("added: %1").arg(change.why);
        case Kind::Removed:
            return MachineHistoryDialog::tr("taken out of the machine");
        case Kind::NotSaved:
            return MachineHistoryDialog::tr("NOT COMPARED: %1").arg(change.why);
        case Kind::NotCompared:
            return MachineHistoryDialog::tr("NOT COMPARED: %1").arg(change.why);
        case Kind::Changed:
            break;
    }
    return change.identity;
}

// The GUI part of family `familyId` (every device holds one of each family).
const FamilyGui* familyGui(const Machine& machine, const QString& familyId) {
    for (const MachineUnit* unit : machine.units())
        for (const FamilyGui* family : unit->families())
            if (family->familyId() == familyId) return family;
    return nullptr;
}

}  // namespace

MachineHistoryDialog::MachineHistoryDialog(Machine* machine, const QString& archive,
                                           QWidget* parent)
    : QDialog(parent),
      m_machine(machine),
      m_versions(new QTreeWidget),
      m_differences(new QTableWidget(0, 5)),
      m_status(new QLabel),
      m_compare(new QPushButton(tr("&Compare the two"))),
      m_compareNow(new QPushButton(tr("Compare with the devices &now"))),
      m_restore(new QPushButton(tr("&Restore this version…"))),
      m_release(new QPushButton(tr("&Mark as released"))),
      m_draw(new QPushButton(tr("&Draw the differences…"))),
      m_jobs(new MachineHistoryJobs(machine, this)) {
    setWindowTitle(tr("History of %1 - %2").arg(machine->name(), archive));
    m_versions->setObjectName(QStringLiteral("machineHistoryVersions"));
    m_versions->setColumnCount(5);
    m_versions->setHeaderLabels({tr("Version"), tr("Time"), tr("Who"), tr("Why"), tr("Released")});
    m_versions->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_versions->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_differences->setObjectName(QStringLiteral("machineHistoryDifferences"));
    m_differences->setHorizontalHeaderLabels(
        {tr("Device"), tr("Item"), tr("Before"), tr("After"), tr("Difference")});
    m_differences->horizontalHeader()->setStretchLastSection(true);
    m_differences->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_differences->verticalHeader()->hide();
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_draw->setObjectName(QStringLiteral("drawDifferences"));
    m_draw->setToolTip(
        tr("The device's changes between the two states compared (two versions, or a version "
           "and the devices now), drawn in its family's terms (a double click on its row does "
           "the same); a table is all there is for a family that draws none."));

    auto* buttons = new QHBoxLayout;
    for (QPushButton* button : {m_compare, m_compareNow, m_draw, m_restore, m_release})
        buttons->addWidget(button);
    buttons->addStretch();
    auto* close = new QDialogButtonBox(QDialogButtonBox::Close);
    buttons->addWidget(close);
    auto* splitter = new QSplitter(Qt::Vertical);
    splitter->addWidget(m_versions);
    splitter->addWidget(m_differences);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(splitter, 1);
    layout->addWidget(m_status);
    layout->addLayout(buttons);

    connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_versions, &QTreeWidget::itemSelectionChanged, this,
            &MachineHistoryDialog::updateButtons);
    connect(m_compare, &QPushButton::clicked, this, &MachineHistoryDialog::compareSelected);
    connect(m_compareNow, &QPushButton::clicked, this,
            &MachineHistoryDialog::compareWithDevicesNow);
    connect(m_restore, &QPushButton::clicked, this, &MachineHistoryDialog::restoreSelected);
    connect(m_release, &QPushButton::clicked, this, &MachineHistoryDialog::markReleased);
    connect(m_draw, &QPushButton::clicked, this, &MachineHistoryDialog::showDrawing);
    connect(m_differences, &QTableWidget::currentCellChanged, this,
            &MachineHistoryDialog::updateButtons);
    connect(m_differences, &QTableWidget::cellDoubleClicked, this,
            &MachineHistoryDialog::showDrawing);

    const Result<MachineArchive> opened = MachineArchive::open(archive);
    if (opened)
        m_archive = *opened;
    else
        say(opened.error().message);
    reload();
    resizeWithinScreen(*this, 1100, 760);
}

MachineHistoryDialog::~MachineHistoryDialog() = default;

void MachineHistoryDialog::say(const QString& text) {
    m_status->setText(text);
}

void MachineHistoryDialog::reload() {
    m_versions->clear();
    m_list.clear();
    if (m_archive) {
        const Result<QList<ArchiveVersion>> versions = m_archive->versions();
        if (versions)
            m_list = *versions;
        else
            say(versions.error().message);
    }
    for (const ArchiveVersion& version : m_list) {
        auto* item = new QTreeWidgetItem(m_versions);
        item->setText(Version, version.shortId());
        item->setData(Version, Qt::UserRole, version.id);
        // As the printed report and `machine history` write it, in every language.
        item->setText(Time, reportTime(version.time));
        item->setText(Author, version.author);
        item->setText(Note, version.note);
        QStringList marks = version.releases;
        if (version.released) marks.prepend(tr("released"));
        item->setText(Released, marks.join(QLatin1String(", ")));
        for (const QString& change : version.changes) {
            auto* line = new QTreeWidgetItem(item);
            line->setText(Note, change);
            line->setFlags(Qt::ItemIsEnabled);  // a line of its version, not a version
        }
        item->setExpanded(true);
    }
    if (m_archive && m_list.isEmpty())
        say(tr("%1 holds no version yet: Machine → Back up… into it, or `cambench-cli machine "
               "backup M.json --archive %1 -m WHY`.")
                .arg(m_archive->dir()));
    updateButtons();
}

QStringList MachineHistoryDialog::selectedIds() const {
    QStringList ids;
    // In the list's order: newest first.
    for (int i = 0; i < m_versions->topLevelItemCount(); ++i)
        if (m_versions->topLevelItem(i)->isSelected())
            ids << m_versions->topLevelItem(i)->data(Version, Qt::UserRole).toString();
    return ids;
}

void MachineHistoryDialog::updateButtons() {
    const int selected = int(selectedIds().size());
    const bool idle = !m_jobs->busy();
    m_compare->setEnabled(idle && selected == 2);
    m_compareNow->setEnabled(idle && selected == 1);
    m_restore->setEnabled(idle && selected == 1);
    m_release->setEnabled(idle && selected == 1);
    m_draw->setEnabled(drawingOf(currentDevice()) != nullptr);
}

QString MachineHistoryDialog::currentDevice() const {
    const QTableWidgetItem* cell = m_differences->item(m_differences->currentRow(), Device);
    return cell ? cell->text() : QString();
}

void MachineHistoryDialog::dropDrawings() {
    for (const QPointer<QDialog>& drawing : std::as_const(m_drawings))
        if (drawing) drawing->deleteLater();
    m_drawings.clear();
}

void MachineHistoryDialog::makeDrawings(const usecases::MachineChanges& changes, const State& older,
                                        const State& newer) {
    const QString& olderLabel = older.label;
    const QString& newerLabel = newer.label;
    for (const usecases::DeviceChange& change : changes.devices) {
        if (change.kind != usecases::DeviceChange::Kind::Changed) continue;
        const ManifestEntry* first = older.folder.manifest.entry(change.name);
        const ManifestEntry* second = newer.folder.manifest.entry(change.name);
        if (!first || !second || first->family != second->family) continue;
        const FamilyGui* family = familyGui(*m_machine, second->family);
        QWidget* drawn = family ? family->backupDrawing(
                                      {QDir(older.folder.dir).filePath(first->file), olderLabel},
                                      {QDir(newer.folder.dir).filePath(second->file), newerLabel})
                                : nullptr;
        if (!drawn) continue;
        auto* drawing = new QDialog(this);
        drawing->setObjectName(QStringLiteral("machineHistoryDrawing"));
        drawing->setWindowTitle(tr("%1: %2 → %3").arg(change.name, olderLabel, newerLabel));
        auto* close = new QDialogButtonBox(QDialogButtonBox::Close);
        connect(close, &QDialogButtonBox::rejected, drawing, &QDialog::reject);
        auto* layout = new QVBoxLayout(drawing);
        layout->addWidget(drawn, 1);
        layout->addWidget(close);
        resizeWithinScreen(*drawing, 1000, 600);
        m_drawings.insert(change.name, drawing);
    }
    if (!m_drawings.isEmpty())
        say(m_status->text() + u' ' +
            tr("Drawn as well: %1 (Draw the differences…, or a double click on its row).")
                .arg(QStringList(m_drawings.keys()).join(QLatin1String(", "))));
}

void MachineHistoryDialog::showDrawing() {
    QDialog* drawing = drawingOf(currentDevice());
    if (!drawing) return;
    drawing->show();
    drawing->raise();
    drawing->activateWindow();
}

void MachineHistoryDialog::showChanges(const usecases::MachineChanges& changes,
                                       const QString& heading) {
    m_differences->setRowCount(0);
    dropDrawings();
    const auto addRow = [this](const QStringList& cells) {
        const int row = m_differences->rowCount();
        m_differences->insertRow(row);
        for (int column = 0; column < cells.size(); ++column)
            m_differences->setItem(row, column, new QTableWidgetItem(cells.at(column)));
    };
    QStringList changed;
    for (const usecases::DeviceChange& device : changes.devices) {
        if (device.kind != usecases::DeviceChange::Kind::Equal &&
            device.kind != usecases::DeviceChange::Kind::NotSaved &&
            device.kind != usecases::DeviceChange::Kind::NotCompared)
            changed << device.name;
        if (device.differences.isEmpty() || !device.identity.isEmpty())
            addRow({device.name, QString(), QString(), QString(), deviceState(device)});
        for (const BackupDifference& difference : device.differences)
            addRow({device.name,
                    difference.key + (difference.what.isEmpty()
                                          ? QString()
                                          : QStringLiteral(" ") + difference.what),
                    difference.oldValue, difference.newValue, difference.text});
    }
    for (const QString& line : changes.machineFile)
        addRow({tr("machine file"), QString(), QString(), QString(), line});
    m_differences->resizeColumnsToContents();
    say(changed.isEmpty() && changes.machineFile.isEmpty()
            ? tr("%1: no difference.").arg(heading)
            : tr("%1: differences in %2.")
                  .arg(heading, changed.isEmpty() ? tr("the machine file")
                                                  : changed.join(QLatin1String(", "))));
    if (!changes.complete())
        say(m_status->text() + u' ' + tr("Not every device was compared (see the table)."));
}

void MachineHistoryDialog::compareSelected() {
    const QStringList ids = selectedIds();
    if (ids.size() != 2 || !m_archive) return;
    const Result<usecases::VersionFolder> newer = usecases::takeOutVersion(*m_archive, ids.at(0));
    const Result<usecases::VersionFolder> older = usecases::takeOutVersion(*m_archive, ids.at(1));
    if (!newer || !older) {
        say((!newer ? newer : older).error().message);
        return;
    }
    const usecases::MachineChanges changes =
        usecases::compareMachineFolders(older->path(), newer->path());
    showChanges(changes, tr("Version %1 → %2").arg(ids.at(1).left(10), ids.at(0).left(10)));
    const Result<usecases::MachineFolderRead> before = usecases::readMachineFolder(older->path());
    const Result<usecases::MachineFolderRead> after = usecases::readMachineFolder(newer->path());
    if (before && after)
        makeDrawings(changes, {*before, tr("version %1").arg(older->id.left(10))},
                     {*after, tr("version %1").arg(newer->id.left(10))});
    updateButtons();
    Q_EMIT finished();
}

bool MachineHistoryDialog::takeOutSelected() {
    const QStringList ids = selectedIds();
    if (ids.size() != 1 || !m_archive) return false;
    Result<usecases::VersionFolder> folder = usecases::takeOutVersion(*m_archive, ids.first());
    if (!folder) {
        say(folder.error().message);
        return false;
    }
    m_folder.emplace(std::move(folder).value());
    return true;
}

void MachineHistoryDialog::compareWithDevicesNow() {
    if (!takeOutSelected()) return;
    const QString id = m_folder->id;
    say(tr("Reading every device to compare it with version %1…").arg(id.left(10)));
    m_jobs->compareWithDevices(
        m_folder->path(), [this, id](const usecases::MachineChanges& changes,
                                     const usecases::MachineFolderRead& now) {
            showChanges(changes, tr("Version %1 → the devices now").arg(id.left(10)));
            // Drawn while the backup now is still there.
            if (const Result<usecases::MachineFolderRead> version =
                    usecases::readMachineFolder(m_folder->path()))
                makeDrawings(changes, {*version, tr("version %1").arg(id.left(10))},
                             {now, tr("the devices now")});
            updateButtons();
            Q_EMIT finished();
        });
    updateButtons();
}

void MachineHistoryDialog::markReleased() {
    const QStringList ids = selectedIds();
    if (ids.size() != 1 || !m_archive) return;
    const Result<QString> tag = m_archive->release(ids.first(), loginName(), {});
    if (!tag) {
        say(tag.error().message);
        return;
    }
    reload();
    say(tr("Version %1 is the released version now (%2).").arg(ids.first().left(10), *tag));
    Q_EMIT finished();
}

void MachineHistoryDialog::restoreSelected() {
    if (!takeOutSelected()) return;
    const QString id = m_folder->id;
    say(tr("Reading each device's plan of restoring version %1…").arg(id.left(10)));
    m_jobs->plan(m_folder->path(), [this, id](QList<MachineHistoryJobs::DevicePlan> plans) {
        updateButtons();
        QString text;
        QStringList ready;
        for (const MachineHistoryJobs::DevicePlan& device : plans) {
            if (!device.plan) {
                text += tr("%1: NOT RESTORED: %2\n").arg(device.name, device.why);
                continue;
            }
            ready << device.name;
            text += tr("%1: %n item(s) to change\n", nullptr, int(device.plan->changes.size()))
                        .arg(device.name);
            for (const QString& step : device.plan->steps)
                text += QStringLiteral("    %1\n").arg(step);
            for (const BackupDifference& change : device.plan->changes)
                text += QStringLiteral("    %1\n").arg(change.text);
        }
        if (ready.isEmpty()) {
            say(tr("Version %1 is not restored: no device can take it.\n%2")
                    .arg(id.left(10), text));
            Q_EMIT finished();
            return;
        }
        QMessageBox question(QMessageBox::Warning, tr("Restore version %1").arg(id.left(10)),
                             tr("Restore version %1 into %2? Each device's plan is in the "
                                "details; a safety copy of what a device holds is taken first "
                                "where its family takes one.")
                                 .arg(id.left(10), ready.join(QLatin1String(", "))),
                             QMessageBox::Yes | QMessageBox::Cancel, this);
        question.setObjectName(QStringLiteral("restoreVersionQuestion"));
        question.setDetailedText(text);
        question.setDefaultButton(QMessageBox::Cancel);
        if (question.exec() != QMessageBox::Yes) {
            say(tr("Version %1 was not restored; nothing was written.").arg(id.left(10)));
            Q_EMIT finished();
            return;
        }
        const QString safety = safetyFolderPath(m_archive->dir(), QDateTime::currentDateTimeUtc());
        m_jobs->restore(
            m_folder->path(), ready, safety,
            [this, id](QList<MachineHistoryJobs::DeviceRestored> lines) {
                QStringList said;
                for (const auto& line : lines)
                    said << QStringLiteral("%1: %2").arg(line.name, line.text);
                say(tr("Restore of version %1:\n%2").arg(id.left(10), said.join(u'\n')));
                updateButtons();
                Q_EMIT finished();
            });
        updateButtons();
    });
    updateButtons();
}

void openMachineHistory(Machine* machine, QWidget* parent) {
    const QString start =
        machine->path().isEmpty() ? QString() : QFileInfo(machine->path()).absolutePath();
    const QString archive = QFileDialog::getExistingDirectory(
        parent, MachineHistoryDialog::tr("The archive of %1").arg(machine->name()), start);
    if (archive.isEmpty()) return;
    auto* dialog = new MachineHistoryDialog(machine, archive, parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
}

}  // namespace cambench
