#include "compax3_watch_page.h"

#include "compax3_gui.h"

#include "comm/compax3/usecases/compax3_read_objects.h"
#include "ui/device_session.h"
#include "ui/language.h"
#include "ui/live_freshness.h"
#include "ui/multi_trend_chart.h"
#include "ui/sentence.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

namespace cambench {

namespace {
enum Column { ObjectColumn, NameColumn, ValueColumn, ReadColumn };
}  // namespace

Compax3WatchPage::Compax3WatchPage(DeviceSession* session, Compax3Gui* gui, QWidget* parent)
    : Compax3Page(session, parent),
      m_gui(gui),
      m_add(new QLineEdit),
      m_table(new QTableWidget(0, 4)),
      m_chart(new MultiTrendChart) {
    setObjectName(QStringLiteral("compax3WatchPage"));
    m_add->setObjectName(QStringLiteral("compax3WatchAdd"));
    m_add->setPlaceholderText(tr("Object to watch, e.g. 680.5"));
    connect(m_add, &QLineEdit::returnPressed, this, [this] {
        if (addObject(m_add->text())) m_add->clear();
    });
    auto* add = new QPushButton(tr("Add"));
    connect(add, &QPushButton::clicked, this, [this] {
        if (addObject(m_add->text())) m_add->clear();
    });
    auto* remove = new QPushButton(tr("Remove selected"));
    connect(remove, &QPushButton::clicked, this, [this] {
        QList<int> rows;
        for (const QModelIndex& index : m_table->selectionModel()->selectedRows())
            rows << index.row();
        std::sort(rows.rbegin(), rows.rend());
        for (int row : rows) m_gui->watchList().removeAt(row);
        rebuildTable();
        m_chart->clear();
    });
    m_table->setObjectName(QStringLiteral("compax3WatchTable"));
    m_table->setHorizontalHeaderLabels({tr("Object"), tr("Name"), tr("Value"), tr("Read")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_chart->setObjectName(QStringLiteral("compax3WatchChart"));
    auto* top = new QHBoxLayout;
    top->addWidget(m_add, 1);
    top->addWidget(add);
    top->addWidget(remove);
    auto* split = new QSplitter(Qt::Vertical);
    split->addWidget(m_table);
    split->addWidget(m_chart);
    split->setStretchFactor(1, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(split, 1);
    layout->addWidget(freshnessLine());
    layout->addWidget(resultLine());
    rebuildTable();
}

bool Compax3WatchPage::addObject(const QString& text) {
    const Result<Compax3ObjectId> id = parseCompax3Object(text);
    if (!id) {
        showResult(asSentence(id.error().message), false);
        return false;
    }
    const Compax3ObjectInfo* info = m_gui->dictionary().find(*id);
    if (info && !info->readable()) {
        showResult(tr("%1 is a function: it is written, never read.").arg(id->text()), false);
        return false;
    }
    if (!m_gui->watchList().contains(*id)) m_gui->watchList() << *id;
    rebuildTable();
    poll();
    return true;
}

void Compax3WatchPage::rebuildTable() {
    const QList<Compax3ObjectId>& ids = m_gui->watchList();
    m_table->setRowCount(int(ids.size()));
    for (int row = 0; row < ids.size(); ++row) {
        const Compax3ObjectInfo* info = m_gui->dictionary().find(ids.at(row));
        const QStringList texts{
            ids.at(row).text(), info ? info->nameIn(currentLanguage()) : QString(), {}, {}};
        for (int column = 0; column < texts.size(); ++column)
            if (!m_table->item(row, column) || column < ValueColumn)
                m_table->setItem(row, column, new QTableWidgetItem(texts.at(column)));
    }
}

bool Compax3WatchPage::poll() {
    if (!facts().known || m_gui->watchList().isEmpty()) return false;
    const QList<Compax3ObjectId> ids = m_gui->watchList();
    using usecases::Compax3Reading;
    runPoll<comm::Compax3Device, QList<Compax3Reading>>(
        tr("Read watched objects"),
        [ids](comm::Compax3Device& device, comm::JobContext&) {
            return usecases::readCompax3Objects(device, ids);
        },
        [this](const QList<Compax3Reading>& values) { show(values); },
        QStringLiteral("compax3-watch"));
    return true;
}

void Compax3WatchPage::show(const QList<usecases::Compax3Reading>& values) {
    const QDateTime now = QDateTime::currentDateTime();
    QList<MultiTrendChart::Sample> samples;
    for (const usecases::Compax3Reading& reading : values) {
        const Compax3ObjectId& id = reading.id;
        const QString& value = reading.value;
        const int row = int(m_gui->watchList().indexOf(id));
        if (row < 0 || row >= m_table->rowCount()) continue;
        const bool refused = reading.refused();
        auto* item = new QTableWidgetItem(refused ? tr("refused") : value);
        item->setToolTip(refused ? reading.refusal.message : QString());
        m_table->setItem(row, ValueColumn, item);
        m_table->setItem(row, ReadColumn,
                         new QTableWidgetItem(now.toString(QStringLiteral("HH:mm:ss.zzz"))));
        if (const std::optional<double> number = compax3Number(value); number && !refused) {
            const QString name = m_table->item(row, NameColumn)->text();
            samples << MultiTrendChart::Sample{
                id.text(),
                name.isEmpty() ? id.text() : QStringLiteral("%1 %2").arg(id.text(), name), *number};
        }
    }
    m_chart->addSamples(now, samples);
}

void Compax3WatchPage::freshnessChanged() {
    // A missed cycle, a lost line, a backup holding the line: grey, and why.
    if (!freshness()->isLive()) greyOut(freshness()->describe());
}

void Compax3WatchPage::greyOut(const QString& why) {
    m_chart->breakLine();
    for (int row = 0; row < m_table->rowCount(); ++row)
        for (int column : {ValueColumn, ReadColumn})
            if (QTableWidgetItem* item = m_table->item(row, column)) {
                item->setForeground(Qt::gray);
                item->setToolTip(why);
            }
}

void Compax3WatchPage::forgetDevice() {
    LiveDevicePage::forgetDevice();
    m_chart->clear();
}

}  // namespace cambench
