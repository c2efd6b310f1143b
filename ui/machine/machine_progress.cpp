#include "machine_progress.h"

#include "machine_unit.h"

#include "ui/device_session.h"

#include <QDialogButtonBox>
#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace cambench {

MachineProgress::MachineProgress(const QString& title, const QList<MachineUnit*>& units,
                                 QWidget* parent)
    : QDialog(parent), m_buttons(new QDialogButtonBox(QDialogButtonBox::Cancel)) {
    setObjectName(QStringLiteral("machineProgress"));
    setWindowTitle(title);
    auto* layout = new QVBoxLayout(this);
    // STOP reachable throughout: the program's (ProgramStop: Escape, and the
    // DialogStop every dialog gets while a device can move) reaches every
    // device of the machine.
    auto* grid = new QGridLayout;
    for (MachineUnit* unit : units) {
        Row row;
        row.unit = unit;
        row.bar = new QProgressBar;
        row.bar->setObjectName(QStringLiteral("progress-%1").arg(unit->name()));
        row.bar->setRange(0, 0);  // busy until its worker says how far
        row.line = new QLabel;
        row.line->setWordWrap(true);
        row.line->setTextInteractionFlags(Qt::TextSelectableByMouse);
        // Room for a result of three lines from the start: a result that
        // comes later neither is cut off nor moves the buttons under the
        // pointer (the whole line is also its tooltip).
        row.line->setAlignment(Qt::AlignLeft | Qt::AlignTop);
        row.line->setMinimumHeight(row.line->fontMetrics().lineSpacing() * 3);
        const int at = grid->rowCount();
        grid->addWidget(new QLabel(unit->name()), at, 0);
        grid->addWidget(row.bar, at, 1);
        grid->addWidget(row.line, at + 1, 1);
        m_rows << row;
        // The bar follows the jobs of this device's own worker.
        const QString name = unit->name();
        connect(&unit->session()->worker(), &comm::JobRunner::jobProgress, this,
                [this, name](quint64, qint64 done, qint64 total, const QString&) {
                    Row* row = rowOf(name);
                    if (!row || row->done || total <= 0) return;
                    row->bar->setRange(0, 1000);
                    row->bar->setValue(int(done * 1000 / total));
                });
    }
    grid->setColumnStretch(1, 1);
    layout->addLayout(grid);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::rejected, this, [this] {
        if (allFinished()) {
            accept();
            return;
        }
        cancelAll();
    });
    setMinimumWidth(520);
}

MachineProgress::Row* MachineProgress::rowOf(const QString& name) {
    for (Row& row : m_rows)
        if (row.unit->name() == name) return &row;
    return nullptr;
}

const MachineProgress::Row* MachineProgress::rowOf(const QString& name) const {
    for (const Row& row : m_rows)
        if (row.unit->name() == name) return &row;
    return nullptr;
}

void MachineProgress::cancelAll() {
    m_cancelled = true;
    // What runs on each device ends at its next request; each device's
    // line then says what was done.
    for (const Row& row : m_rows)
        if (!row.done) row.unit->session()->worker().cancelAll();
}

void MachineProgress::finish(const MachineUnit* unit, bool ok, const QString& line) {
    Row* row = rowOf(unit->name());
    if (!row || row->done) return;
    row->done = true;
    row->bar->setRange(0, 1000);
    if (ok) row->bar->setValue(1000);
    row->line->setText(line);
    row->line->setToolTip(line);
    row->line->setStyleSheet(ok ? QString() : QStringLiteral("color: #c62828"));
    if (!allFinished()) return;
    m_buttons->setStandardButtons(QDialogButtonBox::Close);
    Q_EMIT finished();
}

void MachineProgress::restart(const MachineUnit* unit) {
    Row* row = rowOf(unit->name());
    if (!row) return;
    row->done = false;
    row->bar->setRange(0, 0);
    row->line->clear();
    row->line->setStyleSheet(QString());
    m_buttons->setStandardButtons(QDialogButtonBox::Cancel);
}

bool MachineProgress::allFinished() const {
    for (const Row& row : m_rows)
        if (!row.done) return false;
    return true;
}

QString MachineProgress::resultLine(const QString& name) const {
    const Row* row = rowOf(name);
    return row && row->done ? row->line->text() : QString();
}

QList<QString> MachineProgress::names() const {
    QList<QString> names;
    for (const Row& row : m_rows) names << row.unit->name();
    return names;
}

QProgressBar* MachineProgress::bar(const QString& name) const {
    const Row* row = rowOf(name);
    return row ? row->bar : nullptr;
}

}  // namespace cambench
