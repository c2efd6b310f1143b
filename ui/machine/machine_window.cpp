#include "machine_window.h"

#include "machine.h"
#include "machine_backup_run.h"
#include "machine_history_dialog.h"
#include "machine_progress.h"
#include "machine_report.h"
#include "machine_report_changes.h"
#include "machine_stop.h"
#include "machine_unit.h"

#include "comm/device/family_registry.h"
#include "ui/device_session.h"
#include "ui/main_window.h"

#include <QCloseEvent>
#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QHash>
#include <QHeaderView>
#include <QInputDialog>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QPainter>
#include <QPointer>
#include <QPushButton>
#include <QScreen>
#include <QScrollBar>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTreeWidget>

namespace cambench {

namespace {

// The lamp of a device's row: green on the line, amber while connecting
// and checking which device answers, red when gone or another device
// answers, grey while offline, blue while it moves.
QIcon lampIcon(MachineUnit::Lamp lamp) {
    // In the order of MachineUnit::Lamp.
    static const QColor colors[] = {QColor(0x2e, 0x7d, 0x32), QColor(0xf9, 0xa8, 0x25),
                                    QColor(0xc6, 0x28, 0x28), QColor(0x9e, 0x9e, 0x9e),
                                    QColor(0xc6, 0x28, 0x28), QColor(0x15, 0x65, 0xc0)};
    const QColor color = colors[int(lamp)];
    QPixmap pixmap(14, 14);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setBrush(color);
    painter.setPen(Qt::NoPen);
    painter.drawEllipse(1, 1, 12, 12);
    return QIcon(pixmap);
}

QString familyTitle(const QString& familyId) {
    const comm::FamilyInfo* info = comm::FamilyRegistry::instance().find(familyId);
    if (!info) return familyId;
    return QCoreApplication::translate("cambench::comm", info->title.toUtf8().constData());
}

}  // namespace

MachineWindow::MachineWindow(Machine* machine, QWidget* parent)
    : QMainWindow(parent),
      m_machine(machine),
      m_list(new QTreeWidget),
      m_stack(new QStackedWidget) {
    setAttribute(Qt::WA_DeleteOnClose, false);
    m_list->setObjectName(QStringLiteral("machineDevices"));
    m_list->setRootIsDecorated(false);
    m_list->setColumnCount(5);
    m_list->setHeaderLabels(
        {tr("Device"), tr("State"), tr("Not written"), tr("Family"), tr("Port")});
    m_list->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_list->header()->setStretchLastSection(false);
    // The state's words may be long ("another device answers: expected
    // ..., found ..."): they wrap in a column of their own width, so that
    // family and port stay in sight whole, in every language.
    m_list->header()->setSectionResizeMode(State, QHeaderView::Interactive);
    constexpr int kStateChars = 30;
    m_list->header()->resizeSection(
        State, std::max(m_list->header()->sectionSizeHint(State),
                        m_list->fontMetrics().averageCharWidth() * kStateChars));
    m_list->setWordWrap(true);
    m_list->setUniformRowHeights(false);
    m_list->setTextElideMode(Qt::ElideNone);
    auto* splitter = new QSplitter;
    splitter->addWidget(m_list);
    splitter->addWidget(m_stack);
    splitter->setStretchFactor(1, 1);
    splitter->setChildrenCollapsible(false);
    setCentralWidget(splitter);
    createMenus();
    for (MachineUnit* unit : machine->units()) addRow(unit);
    connect(machine, &Machine::deviceAdded, this, [this](MachineUnit* unit) {
        addRow(unit);
        showDevice(unit->name());
    });
    connect(m_list, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (!item) return;
        if (MachineUnit* unit = m_machine->unit(item->text(Name))) {
            m_stack->setCurrentWidget(unit->window());
            showMenusOf(unit);
        }
    });
    connect(machine->stop(), &MachineStop::stopFinished, this,
            [this] { showMessage(tr("STOP: %1").arg(m_machine->stop()->lastSummary())); });
    showDevice({});
    updateTitle();
    resize(1600, 900);
}

void MachineWindow::createMenus() {
    m_machineMenu = menuBar()->addMenu(tr("&Machine"));
    QMenu* menu = m_machineMenu;
    menu->addAction(tr("&Add device…"), this, &MachineWindow::addDevice);
    menu->addAction(tr("&Save machine as…"), this, &MachineWindow::saveAs);
    menu->addSeparator();
    // Every device at once, each on its own worker (a bar per device).
    menu->addAction(tr("&Back up…"), this, [this] {
        const QString dir = QFileDialog::getExistingDirectory(this, tr("Back up the machine into"));
        if (dir.isEmpty()) return;
        bool ok = false;
        // The manifest says why (as the command line's -m).
        const QString note = QInputDialog::getText(this, tr("Back up the machine"),
                                                   tr("Why (kept in the backup's manifest):"),
                                                   QLineEdit::Normal, QString(), &ok);
        if (ok) backUpTo(dir, note);
    });
    menu->addAction(tr("&Verify…"), this, [this] {
        const QString dir =
            QFileDialog::getExistingDirectory(this, tr("Verify against the backup"));
        if (!dir.isEmpty()) verifyFrom(dir);
    });
    menu->addAction(tr("R&estore…"), this, [this] {
        const QString dir = QFileDialog::getExistingDirectory(this, tr("Restore the backup"));
        if (!dir.isEmpty()) restoreFrom(dir);
    });
    menu->addSeparator();
    menu->addAction(tr("Machine &report…"), this, &MachineWindow::writeReport);
    menu->addAction(tr("&History…"), this, [this] { openMachineHistory(m_machine, this); });
    menu->addSeparator();
    menu->addAction(tr("&Close machine"), this, &QWidget::close);
}

void MachineWindow::showMenusOf(MachineUnit* unit) {
    for (QAction* action : menuBar()->actions())
        if (action != m_machineMenu->menuAction()) menuBar()->removeAction(action);
    if (!unit || !unit->window()) return;
    // The device's File, Edit, Device, ... menus themselves: what they
    // enable and show follows its line and family as in its own window.
    QMenuBar* own = unit->window()->menuBar();
    own->hide();
    for (QAction* action : own->actions()) menuBar()->addAction(action);
}

void MachineWindow::addRow(MachineUnit* unit) {
    auto* item = new QTreeWidgetItem(m_list);
    item->setText(Name, unit->name());
    item->setTextAlignment(Unwritten, Qt::AlignRight | Qt::AlignVCenter);
    m_stack->addWidget(unit->createWindow());
    // One menu bar: the machine window's shows the device's menus.
    unit->window()->menuBar()->hide();
    updateRow(unit);
    connect(unit, &MachineUnit::changed, this, [this, unit] { updateRow(unit); });
    // One device going away is said once, naming it; the others stay as they are.
    connect(unit->session(), &DeviceSession::stateChanged, this,
            [this, unit](comm::ConnectionState state, const QString& message) {
                if (state == comm::ConnectionState::Lost)
                    showMessage(tr("%1: connection lost (%2); the other devices are not "
                                   "affected.")
                                    .arg(unit->name(), message));
            });
}

QTreeWidgetItem* MachineWindow::rowOf(const MachineUnit* unit) const {
    for (int row = 0; row < m_list->topLevelItemCount(); ++row)
        if (m_list->topLevelItem(row)->text(Name) == unit->name()) return m_list->topLevelItem(row);
    return nullptr;
}

void MachineWindow::updateRow(MachineUnit* unit) {
    QTreeWidgetItem* item = rowOf(unit);
    if (!item) return;
    item->setText(Family, familyTitle(unit->device().family));
    item->setText(Port, unit->device().option(QStringLiteral("port")));
    item->setIcon(State, lampIcon(unit->lamp()));
    item->setText(State, unit->stateText());
    item->setToolTip(State, unit->stateText());
    const int unwritten = unit->unwrittenCount();
    item->setText(Unwritten, unwritten > 0 ? QString::number(unwritten) : QString());
    fitColumns();
    updateTitle();
}

void MachineWindow::fitColumns() {
    QHeaderView* header = m_list->header();
    int width = 2 * m_list->frameWidth();
    for (int column = 0; column < m_list->columnCount(); ++column) {
        if (column != State) m_list->resizeColumnToContents(column);
        width += header->sectionSize(column);
    }
    width += m_list->verticalScrollBar()->sizeHint().width();
    // Every column in sight where the screen has room for them beside the
    // device's window; on a narrower screen (a laptop's 1366 pixels, German
    // words) the list scrolls sideways instead of pushing the window's
    // right edge off the screen.
    constexpr int kLeastListChars = 24;
    const int least = m_list->fontMetrics().averageCharWidth() * kLeastListChars;
    const int room = screen()->availableGeometry().width() - m_stack->minimumSizeHint().width() -
                     static_cast<QSplitter*>(centralWidget())->handleWidth();
    m_list->setMinimumWidth(std::clamp(room, least, std::max(least, width)));
    // Rows grow with a state that wraps to another line.
    m_list->doItemsLayout();
}

void MachineWindow::updateTitle() {
    int unwritten = 0;
    for (const MachineUnit* unit : m_machine->units()) unwritten += unit->unwrittenCount();
    QString title = tr("CamBench – machine %1").arg(m_machine->name()) + QStringLiteral("[*]");
    if (unwritten > 0)
        title += QLatin1Char(' ') + tr("[%n change(s) not written]", nullptr, unwritten);
    setWindowTitle(title);
    setWindowModified(unwritten > 0);
}

QString MachineWindow::currentDevice() const {
    const QTreeWidgetItem* item = m_list->currentItem();
    return item ? item->text(Name) : QString();
}

void MachineWindow::showDevice(const QString& name) {
    MachineUnit* unit = m_machine->unit(name);
    if (!unit && !m_machine->units().isEmpty()) unit = m_machine->units().first();
    if (!unit) return;
    m_list->setCurrentItem(rowOf(unit));
    m_stack->setCurrentWidget(unit->window());
    showMenusOf(unit);
}

void MachineWindow::showMessage(const QString& text) {
    m_lastMessage = text;
    constexpr int kMessageMs = 15000;  // a STOP's report is read twice
    statusBar()->showMessage(text, kMessageMs);
}

void MachineWindow::saveAs() {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save machine"),
        m_machine->path().isEmpty() ? m_machine->name() + QStringLiteral(".json")
                                    : m_machine->path(),
        tr("Machine file (*.json)"));
    if (path.isEmpty()) return;
    const Status saved = m_machine->save(path);
    if (!saved) {
        QMessageBox::warning(this, tr("Save machine"), saved.error().message);
        return;
    }
    showMessage(tr("Machine saved to %1.").arg(QFileInfo(path).fileName()));
}

void MachineWindow::writeReport() {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Machine report"), m_machine->name() + QStringLiteral(".pdf"), tr("PDF (*.pdf)"));
    if (path.isEmpty()) return;
    // The archive is not part of the machine file: asked each time.
    QMessageBox question(QMessageBox::Question, tr("Machine report"),
                         tr("Add the changes since the released version? Each device is then "
                            "compared with its backup in the version released in the machine's "
                            "archive."),
                         QMessageBox::NoButton, this);
    question.setObjectName(QStringLiteral("reportChangesQuestion"));
    QPushButton* choose = question.addButton(tr("Choose the archive…"), QMessageBox::AcceptRole);
    question.addButton(tr("Without"), QMessageBox::RejectRole);
    question.exec();
    QString archive;
    if (question.clickedButton() == choose)
        archive = QFileDialog::getExistingDirectory(
            this, tr("The archive of %1").arg(m_machine->name()),
            m_machine->path().isEmpty() ? QString() : QFileInfo(m_machine->path()).absolutePath());
    writeReportTo(path, archive);
}

MachineProgress* MachineWindow::writeReportTo(const QString& path, const QString& archive) {
    // Everything is read before it is printed: a bar per device.
    auto* progress = new MachineProgress(tr("Machine report"), m_machine->units(), this);
    progress->setAttribute(Qt::WA_DeleteOnClose);
    progress->show();
    QPointer<MachineProgress> shown(progress);
    const auto write = [this, shown, path](const ReleasedChanges& released) {
        const Status written = MachineReport::write(path, *m_machine, &released);
        const QString message =
            written ? tr("Machine report written to %1.").arg(QFileInfo(path).fileName())
                    : written.error().message;
        showMessage(message);
        if (!written)
            QMessageBox::warning(shown ? static_cast<QWidget*>(shown.data()) : this,
                                 tr("Machine report"), message);
    };
    MachineReport::read(*m_machine, progress, [this, shown, archive, write] {
        if (archive.isEmpty()) {
            write(ReleasedChanges{});
            return;
        }
        // Each device's line: what its read said, then its comparison.
        QHash<QString, QString> readLines;
        if (shown)
            for (MachineUnit* unit : m_machine->units()) {
                readLines.insert(unit->name(), shown->resultLine(unit->name()));
                shown->restart(unit);
            }
        MachineReportChanges::compare(
            m_machine, archive, this, [this, shown, readLines, write](ReleasedChanges released) {
                if (shown)
                    for (MachineUnit* unit : m_machine->units()) {
                        QString line = tr("not compared: %1").arg(released.problem);
                        bool ok = false;
                        for (const usecases::DeviceChange& change : released.changes.devices)
                            if (change.name == unit->name()) {
                                line = MachineReportChanges::deviceLine(change);
                                ok = change.kind == usecases::DeviceChange::Kind::Equal ||
                                     change.kind == usecases::DeviceChange::Kind::Changed;
                            }
                        shown->finish(
                            unit, ok,
                            QStringLiteral("%1; %2").arg(readLines.value(unit->name()), line));
                    }
                write(released);
            });
    });
    return progress;
}

MachineBackupRun* MachineWindow::backUpTo(const QString& dir, const QString& note) {
    return MachineBackupRun::backUp(m_machine, dir, note, this);
}

MachineBackupRun* MachineWindow::verifyFrom(const QString& dir) {
    return MachineBackupRun::verify(m_machine, dir, this);
}

MachineBackupRun* MachineWindow::restoreFrom(const QString& dir) {
    return MachineBackupRun::restore(m_machine, dir, this);
}

void MachineWindow::addDevice() {
    // Its port and protocol are chosen on its own Connection page (Detect
    // finds them); the machine file takes what it connected with.
    MachineDevice device;
    device.name = QInputDialog::getText(this, tr("Add device"),
                                        tr("Name of the device in this machine (e.g. feed):"))
                      .trimmed();
    if (device.name.isEmpty()) return;
    const Result<MachineUnit*> added = m_machine->addDevice(device);
    if (!added) {
        QMessageBox::warning(this, tr("Add device"), added.error().message);
        return;
    }
    showMessage(tr("%1: choose its port on its Connection page (Detect finds the protocol), then "
                   "Connect.")
                    .arg(device.name));
}

bool MachineWindow::confirmClose() {
    for (MachineUnit* unit : m_machine->units()) {
        if (!unit->window()) continue;
        // The question names the device: show its pages first.
        showDevice(unit->name());
        if (!unit->window()->confirmClose()) return false;
    }
    return true;
}

void MachineWindow::closeEvent(QCloseEvent* event) {
    if (!confirmClose()) {
        event->ignore();
        return;
    }
    event->accept();
    Q_EMIT closed();
}

}  // namespace cambench
