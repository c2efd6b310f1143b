#include "machine_window.h"

#include "machine.h"
#include "machine_history_dialog.h"
#include "machine_report.h"
#include "machine_stop.h"
#include "machine_unit.h"

#include "comm/device/family_registry.h"
#include "ui/device_session.h"
#include "ui/main_window.h"

#include <QCloseEvent>
#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QInputDialog>
#include <QMenuBar>
#include <QMessageBox>
#include <QPainter>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTreeWidget>

namespace cambench {

namespace {

// The lamp of a device's row: green on the line, amber while connecting,
// red when gone, grey while offline, blue while it moves.
QIcon lampIcon(MachineUnit::Lamp lamp) {
    // In the order of MachineUnit::Lamp.
    static const QColor colors[] = {QColor(0x2e, 0x7d, 0x32), QColor(0xf9, 0xa8, 0x25),
                                    QColor(0xc6, 0x28, 0x28), QColor(0x9e, 0x9e, 0x9e),
                                    QColor(0x15, 0x65, 0xc0)};
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
    // Wide enough for the name, the lamp and its words and the count; family
    // and port scroll into view where the screen is narrow.
    m_list->setMinimumWidth(280);
    auto* splitter = new QSplitter;
    splitter->addWidget(m_list);
    splitter->addWidget(m_stack);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({380, 1220});
    setCentralWidget(splitter);
    createMenus();
    for (MachineUnit* unit : machine->units()) addRow(unit);
    connect(machine, &Machine::deviceAdded, this, [this](MachineUnit* unit) {
        addRow(unit);
        showDevice(unit->name());
    });
    connect(m_list, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (!item) return;
        if (MachineUnit* unit = m_machine->unit(item->text(Name)))
            m_stack->setCurrentWidget(unit->window());
    });
    connect(machine->stop(), &MachineStop::stopFinished, this,
            [this] { showMessage(tr("STOP: %1").arg(m_machine->stop()->lastSummary())); });
    showDevice({});
    updateTitle();
    resize(1600, 900);
}

void MachineWindow::createMenus() {
    QMenu* menu = menuBar()->addMenu(tr("&Machine"));
    menu->addAction(tr("&Add device…"), this, &MachineWindow::addDevice);
    menu->addAction(tr("&Save machine as…"), this, &MachineWindow::saveAs);
    menu->addAction(tr("Machine &report…"), this, &MachineWindow::writeReport);
    menu->addAction(tr("&History…"), this, [this] { openMachineHistory(m_machine, this); });
    menu->addSeparator();
    menu->addAction(tr("&Close machine"), this, &QWidget::close);
}

void MachineWindow::addRow(MachineUnit* unit) {
    auto* item = new QTreeWidgetItem(m_list);
    item->setText(Name, unit->name());
    item->setTextAlignment(Unwritten, Qt::AlignRight | Qt::AlignVCenter);
    m_stack->addWidget(unit->createWindow());
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
    updateTitle();
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
    const Status written = MachineReport::write(path, *m_machine);
    if (!written) {
        QMessageBox::warning(this, tr("Machine report"), written.error().message);
        return;
    }
    showMessage(tr("Machine report written to %1.").arg(QFileInfo(path).fileName()));
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
