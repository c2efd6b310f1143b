#include "plc_page.h"

#include "device_reads.h"
#include "plc_matrix_model.h"
#include "plc_symbol.h"
#include "ui/change_marker.h"
#include "ui/device_session.h"
#include "ui/report_dialog.h"
#include "workspace.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QRegularExpressionValidator>
#include <QSpinBox>
#include <QTableView>
#include <QVBoxLayout>

namespace cambench {

namespace {
constexpr int kMaxNumber = 249;  // 0..248 on the device, shown from 1

QString networkText(const PlcNetwork& n) {
    QStringList symbols;
    for (quint16 word : n.symbols) symbols << plcsymbol::editText(word);
    return QStringLiteral("%1 / %2 / %3")
        .arg(n.value)
        .arg(plcsymbol::editText(n.reset), symbols.join(QLatin1Char(' ')));
}
}  // namespace

QString PlcPage::networkName(int area, int number) {
    return QStringLiteral("%1%2")
        .arg(QLatin1Char(plcsymbol::areaLetter(area)))
        .arg(number + 1, 3, 10, QLatin1Char('0'));
}

PlcPage::PlcPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : CamConSectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_model(new PlcMatrixModel(workspace, this)),
      m_area(new QComboBox),
      m_number(new QSpinBox),
      m_value(new QSpinBox),
      m_reset(new QLineEdit),
      m_matrix(new QTableView),
      m_networks(new QListWidget),
      m_refusal(new QLabel) {
    m_area->addItem(tr("O – physical outputs"), int(PlcNetwork::O));
    m_area->addItem(tr("P – cam controller inputs"), int(PlcNetwork::P));
    m_area->addItem(tr("M – flags"), int(PlcNetwork::M));
    m_area->addItem(tr("X – X flags"), int(PlcNetwork::X));
    m_number->setRange(1, kMaxNumber);
    ReadWriteBar bar([this] { readNetwork(); }, [this] { writeChanges(); });
    bar.readText = tr("Read network");
    bar.before = {new QLabel(tr("Area:")), m_area, new QLabel(tr("Number:")), m_number};
    QHBoxLayout* top = readWriteBar(bar);

    m_value->setRange(std::numeric_limits<qint32>::min(), std::numeric_limits<qint32>::max());
    m_value->setToolTip(tr("Preset of a timer or counter driving this output."));
    m_reset->setInputMask(QStringLiteral("HHHH"));
    m_reset->setToolTip(tr("Reset field for counters, 4 hex digits."));
    auto* fields = new QGroupBox(tr("Network"));
    auto* form = new QFormLayout(fields);
    form->addRow(tr("Value (timer/counter):"), m_value);
    form->addRow(tr("Reset field (hex):"), m_reset);

    m_matrix->setModel(m_model);
    // A refused entry says why where the user typed it, until the next edit.
    m_refusal->setWordWrap(true);
    m_refusal->setObjectName(QStringLiteral("plcRefusal"));
    QPalette alarm = m_refusal->palette();
    alarm.setColor(QPalette::WindowText, QColor(0xd0, 0x40, 0x2e));
    m_refusal->setPalette(alarm);
    m_refusal->hide();
    connect(m_model, &PlcMatrixModel::entryRefused, this, [this](const QString& reason) {
        m_refusal->setText(reason);
        m_refusal->show();
        Q_EMIT statusMessage(reason);
    });
    connect(m_model, &QAbstractItemModel::dataChanged, m_refusal, &QWidget::hide);
    m_matrix->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_matrix->verticalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_matrix->setEditTriggers(QAbstractItemView::AllEditTriggers);
    auto* note =
        new QLabel(tr("Symbols are decoded provisionally (high byte operand kind, low byte "
                      "number; empty = 0000). Unknown words are shown as hex; every cell "
                      "accepts 4 hex digits or a form like M11."));
    note->setWordWrap(true);

    auto* center = new QVBoxLayout;
    center->addWidget(fields);
    center->addWidget(m_matrix, 1);
    center->addWidget(m_refusal);
    center->addWidget(note);

    m_networks->setMaximumWidth(200);
    m_networks->setToolTip(tr("Networks read or edited in this session"));
    auto* body = new QHBoxLayout;
    body->addWidget(m_networks);
    body->addLayout(center, 1);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addLayout(body, 1);

    const auto select = [this] {
        if (!m_updating) showNetwork(m_area->currentData().toInt(), m_number->value() - 1);
    };
    connect(m_area, &QComboBox::currentIndexChanged, this, select);
    connect(m_number, &QSpinBox::valueChanged, this, select);
    connect(m_value, &QSpinBox::valueChanged, this, &PlcPage::editFields);
    connect(m_reset, &QLineEdit::textEdited, this, &PlcPage::editFields);
    connect(m_networks, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        const int key = item->data(Qt::UserRole).toInt();
        showNetwork(key >> 8, key & 0xFF);
    });
    connect(m_workspace, &Workspace::plcChanged, this, [this] {
        showFields();
        fillList();
    });
    showNetwork(PlcNetwork::O, 0);
}

QString PlcPage::refusalText() const {
    return m_refusal->isHidden() ? QString() : m_refusal->text();
}

void PlcPage::showNetwork(int area, int number) {
    m_updating = true;
    m_area->setCurrentIndex(m_area->findData(area));
    m_number->setValue(number + 1);
    m_updating = false;
    m_model->setNetwork(area, number);
    showFields();
}

void PlcPage::showFields() {
    const PlcNetwork network = m_workspace->plcNetwork(m_model->area(), m_model->number());
    m_updating = true;
    m_value->setValue(network.value);
    m_reset->setText(plcsymbol::editText(network.reset));
    m_updating = false;
}

void PlcPage::editFields() {
    if (m_updating) return;
    PlcNetwork network = m_workspace->plcNetwork(m_model->area(), m_model->number());
    network.value = m_value->value();
    bool ok = false;
    const uint reset = m_reset->text().toUInt(&ok, 16);
    if (ok) network.reset = quint16(reset);
    m_workspace->plc().edit(Workspace::plcKey(network.area, network.number), network);
}

void PlcPage::fillList() {
    m_networks->clear();
    const QMap<int, PlcNetwork> networks = m_workspace->plc().shown();
    for (auto it = networks.cbegin(); it != networks.cend(); ++it) {
        const bool changed = m_workspace->plc().isChanged(it.key());
        auto* item = new QListWidgetItem((changed ? changedMarker() : QString()) +
                                         networkName(it->area, it->number));
        item->setData(Qt::UserRole, it.key());
        if (changed) item->setFont(changedFont());
        m_networks->addItem(item);
    }
}

void PlcPage::readNetwork() {
    const int area = m_model->area();
    const int number = m_model->number();
    const QString name = networkName(area, number);
    devicereads::readPlcNetwork(
        this, m_session, m_workspace, area, number,
        reportRead(
            tr("Reading %1…").arg(name), [name] { return tr("%1 read.").arg(name); },
            tr("Reading %1 failed: %2").arg(name, QStringLiteral("%1"))));
}

int PlcPage::itemCount() const {
    return int(m_workspace->plc().shown().size());
}

QList<SectionDifference> PlcPage::differences() const {
    QList<SectionDifference> list;
    for (int key : m_workspace->plc().changedKeys()) {
        const PlcNetwork edited = m_workspace->plc().value(key).value_or(PlcNetwork{});
        const std::optional<PlcNetwork> device = m_workspace->plc().deviceValue(key);
        list.append({WorkspaceItem::plcNetwork(key),
                     tr("Network %1").arg(networkName(edited.area, edited.number)),
                     device ? networkText(*device) : tr("not read"), networkText(edited)});
    }
    return list;
}

void PlcPage::writeChanges(std::function<void(const WriteResult&)> done) {
    writeDifferences(m_session, m_workspace, std::move(done));
}

}  // namespace cambench
