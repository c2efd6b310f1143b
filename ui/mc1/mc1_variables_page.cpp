#include "mc1_variables_page.h"

#include "mc1_value_delegate.h"
#include "mc1_watch_model.h"

#include "ui/device_session.h"
#include "ui/live_freshness.h"
#include "ui/sentence.h"

#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableView>
#include <QVBoxLayout>

namespace cambench {

namespace {
// Polling reads one variable a telegram: the first ones shown stay live.
constexpr int kMaxPolled = 64;
}  // namespace

Mc1VariablesPage::Mc1VariablesPage(DeviceSession* session, Mc1WatchModel* model, QWidget* parent)
    : Mc1Page(session, parent),
      m_model(model),
      m_table(new QTableView),
      m_first(new QSpinBox),
      m_last(new QSpinBox) {
    setObjectName(QStringLiteral("mc1VariablesPage"));
    m_table->setObjectName(QStringLiteral("mc1WatchTable"));
    m_table->setModel(m_model);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->horizontalHeader()->setSectionResizeMode(Mc1WatchModel::NameColumn,
                                                      QHeaderView::Stretch);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_table->setItemDelegateForColumn(Mc1WatchModel::ValueColumn,
                                      new Mc1ValueDelegate(m_model, m_table));
    for (QSpinBox* box : {m_first, m_last}) {
        box->setRange(0, 0xFFFF);
        box->setPrefix(QStringLiteral("V"));
    }
    m_first->setObjectName(QStringLiteral("mc1WatchFirst"));
    m_last->setObjectName(QStringLiteral("mc1WatchLast"));
    m_first->setValue(1);
    m_last->setValue(10);
    auto* add = new QPushButton(tr("Watch"));
    add->setObjectName(QStringLiteral("mc1WatchAdd"));
    auto* remove = new QPushButton(tr("Remove selected"));
    auto* open = new QPushButton(tr("Open list…"));
    open->setToolTip(
        tr("A watch list saved before (MC-1 project file): its variables, names "
           "and the values they had then, shown as not read until read."));
    auto* save = new QPushButton(tr("Save list…"));
    save->setToolTip(
        tr("The watch list with its names and the values last read, as an MC-1 "
           "project file on this PC."));
    auto* import = new QPushButton(tr("Import names…"));
    import->setToolTip(
        tr("A CSV file of \"number;name\" lines, e.g. from the PLC program's "
           "variable list. The names stay on this PC."));
    auto* controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("From")));
    controls->addWidget(m_first);
    controls->addWidget(new QLabel(tr("to")));
    controls->addWidget(m_last);
    controls->addWidget(add);
    controls->addSpacing(12);
    controls->addWidget(remove);
    controls->addWidget(import);
    controls->addWidget(open);
    controls->addWidget(save);
    controls->addStretch();
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(controls);
    layout->addWidget(m_table, 1);
    layout->addWidget(freshnessLine());
    layout->addWidget(resultLine());

    connect(add, &QPushButton::clicked, this, &Mc1VariablesPage::addRange);
    connect(remove, &QPushButton::clicked, this, [this] {
        QList<int> rows;
        for (const QModelIndex& index : m_table->selectionModel()->selectedRows())
            rows << index.row();
        m_model->removeRows(rows);
    });
    connect(import, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Import variable names"), {}, tr("CSV files (*.csv *.txt);;All files (*)"));
        if (!path.isEmpty()) importNames(path);
    });
    connect(open, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Open watch list"), {},
                                                          tr("MC-1 projects (*.json)"));
        if (!path.isEmpty()) openList(path);
    });
    connect(save, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save watch list"),
                                                          QStringLiteral("mc1-project.json"),
                                                          tr("MC-1 projects (*.json)"));
        if (!path.isEmpty()) saveList(path);
    });
    connect(m_model, &Mc1WatchModel::writeRequested, this, &Mc1VariablesPage::writeVariable);
    connect(m_model, &Mc1WatchModel::typedInvalid, this, [this](int number, const QString& typed) {
        showResult(tr("\"%1\" is not a whole number: V%2 was not written.").arg(typed).arg(number),
                   false);
    });
}

void Mc1VariablesPage::addRange() {
    const int first = std::min(m_first->value(), m_last->value());
    const int last = std::max(m_first->value(), m_last->value());
    const int added = m_model->addRange(first, last);
    showResult(tr("%n variable(s) added to the watch list.", nullptr, added), true);
    poll();
}

void Mc1VariablesPage::importNames(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        showResult(
            tr("%1 could not be read: %2. Nothing was imported.").arg(path, file.errorString()),
            false);
        return;
    }
    const Mc1NameList list = parseMc1NameList(file.readAll());
    if (!list.error.isEmpty()) {
        showResult(tr("%1 is not a name list (%2). Nothing was imported.").arg(path, list.error),
                   false);
        return;
    }
    m_model->setNames(list.names);
    showResult(tr("%n name(s) imported from %1.", nullptr, int(list.names.size())).arg(path), true);
}

void Mc1VariablesPage::saveList(const QString& path) {
    const QString variant =
        facts().known ? comm::mc1VariantKey(facts().variant) : QStringLiteral("auto");
    const Status saved = saveMc1Project(path, m_model->toProject(variant));
    showResult(saved
                   ? tr("Watch list saved to %1.").arg(path)
                   : tr("The watch list was not saved: %1").arg(asSentence(saved.error().message)),
               saved.ok());
}

void Mc1VariablesPage::openList(const QString& path) {
    const Result<Mc1Project> project = loadMc1Project(path);
    if (!project) {
        showResult(tr("Nothing was opened: %1").arg(asSentence(project.error().message)), false);
        return;
    }
    m_model->setProject(*project);
    showResult(tr("%n variable(s) from %1; values shown as in the file until read.", nullptr,
                  int(project->variables.size()))
                   .arg(path),
               true);
    poll();
}

bool Mc1VariablesPage::poll() {
    if (!facts().known || m_model->rowCount() == 0) return true;
    const QList<int> numbers = m_model->numbers().mid(0, kMaxPolled);
    runPoll<comm::Mc1Device, QList<qint64>>(
        tr("Read variables"),
        [numbers](comm::Mc1Device& device, comm::JobContext& job) -> Result<QList<qint64>> {
            QList<qint64> values;
            for (int n : numbers) {
                if (job.cancelled()) return Error::cancelled();
                const Result<qint64> value = device.readVariable(n);
                if (!value) return value.error();
                values << *value;
                // Answers are arriving: a long list is slow, not silent.
                job.progress(values.size(), numbers.size());
            }
            return values;
        },
        [this, numbers](const QList<qint64>& values) {
            // The list may have changed while the poll ran: only a match is shown.
            if (m_model->numbers().mid(0, kMaxPolled) == numbers)
                m_model->setValues(values, QDateTime::currentDateTime());
        },
        QStringLiteral("mc1-variables"));
    return true;
}

void Mc1VariablesPage::markStale() {
    m_model->markStale(freshness()->valueNote());
}

void Mc1VariablesPage::freshnessChanged() {
    if (!freshness()->isLive()) markStale();
}

void Mc1VariablesPage::writeVariable(int number, qint64 value, const QString& typed) {
    if (!facts().known) {
        showResult(tr("Not connected to an MC100/MC200: nothing was written."), false);
        return;
    }
    const QString controller = comm::mc1VariantName(facts().variant);
    if (!confirm(tr("Write"),
                 tr("Write V%1 = %2 to the %3?")
                     .arg(number)
                     .arg(typed.isEmpty() ? QString::number(value) : typed)
                     .arg(controller),
                 tr("The controller's PLC program uses this variable at once.")))
        return;
    session()->run<comm::Mc1Device, qint64>(
        this, tr("Write variable"),
        [number, value](comm::Mc1Device& device, comm::JobContext&) -> Result<qint64> {
            if (const Status written = device.writeVariable(number, value); !written)
                return written.error();
            return device.readVariable(number);
        },
        [this, number, value](Result<qint64> back) {
            if (!back) {
                showResult(
                    tr("V%1 was not written: %2").arg(number).arg(asSentence(back.error().message)),
                    false);
                return;
            }
            m_model->setValue(number, *back, QDateTime::currentDateTime());
            showResult(*back == value ? tr("V%1 = %2 written and read back.").arg(number).arg(*back)
                                      : tr("V%1 reads back %2, not the %3 written.")
                                            .arg(number)
                                            .arg(*back)
                                            .arg(value),
                       *back == value);
        });
}

}  // namespace cambench
