#include "mc1_axis_parameters_box.h"

#include "ui/device_session.h"

#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

namespace cambench {

namespace {

const QString kRememberedKey = QStringLiteral("mc1/axisParameterTable");

Result<comm::Mc1AxisParameterTable> readTable(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return Error::invalidData(file.errorString());
    return comm::parseMc1AxisParameterTable(file.readAll(), path);
}

}  // namespace

Mc1AxisParametersBox::Mc1AxisParametersBox(DeviceSession* session, QWidget* parent)
    : QWidget(parent),
      m_session(session),
      m_source(new QLabel),
      m_load(new QPushButton(tr("Load parameter table…"))) {
    m_source->setObjectName(QStringLiteral("mc1ParameterSource"));
    m_source->setWordWrap(true);
    m_load->setObjectName(QStringLiteral("mc1LoadParameters"));
    m_load->setToolTip(
        tr("A CSV file of name,axis,parameter lines (name: position, target or status) from the "
           "controller's MC-1B manual: the RDSTAT parameter numbers of its axes."));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_source, 1);
    layout->addWidget(m_load);
    connect(m_load, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Load parameter table"), {}, tr("CSV files (*.csv *.txt);;All files (*)"));
        if (!path.isEmpty()) load(path);
    });
    showTable();
}

bool Mc1AxisParametersBox::load(const QString& path) {
    const Result<comm::Mc1AxisParameterTable> table = readTable(path);
    if (!table) {
        QMessageBox::warning(this, tr("Load parameter table"),
                             tr("%1 was not loaded: %2\nThe table in use stays: %3")
                                 .arg(path, table.error().message, m_table.source));
        return false;
    }
    QSettings().setValue(kRememberedKey, path);
    use(*table);
    return true;
}

void Mc1AxisParametersBox::controllerOnLine() {
    const QString path = QSettings().value(kRememberedKey).toString();
    if (path.isEmpty()) {
        use(m_table);
        return;
    }
    const Result<comm::Mc1AxisParameterTable> table = readTable(path);
    if (table) {
        use(*table);
        return;
    }
    // The remembered file is gone or changed: the guess, said as such.
    use(comm::mc1ProvisionalAxisParameters());
    m_source->setText(m_source->text() + QLatin1Char('\n') +
                      tr("The table loaded last (%1) could not be read again: %2")
                          .arg(path, table.error().message));
}

void Mc1AxisParametersBox::use(const comm::Mc1AxisParameterTable& table) {
    m_table = table;
    showTable();
    m_session->run<comm::Mc1Device, bool>(
        this, tr("Use parameter table"),
        [table](comm::Mc1Device& device, comm::JobContext&) -> Result<bool> {
            device.setAxisParameters(table);
            return true;
        },
        [this](Result<bool>) { Q_EMIT tableChanged(); });
}

void Mc1AxisParametersBox::showTable() {
    m_source->setText(
        m_table.provisional
            ? tr("Axis parameter numbers: provisional (%1). Positions and states read through them "
                 "are not facts: load the controller's parameter table.")
                  .arg(m_table.source)
            : tr("Axis parameter numbers: from %1.").arg(m_table.source));
}

}  // namespace cambench
