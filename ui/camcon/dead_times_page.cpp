#include "dead_times_page.h"

#include "dead_times_model.h"
#include "device_reads.h"
#include "ui/device_session.h"
#include "workspace.h"

#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/range_delegate.h"

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

namespace cambench {

namespace {

QString ms(qint32 tenths) {
    return QCoreApplication::translate("cambench::DeadTimesModel", "%1 ms")
        .arg(QLocale().toString(tenths / 10.0, 'f', 1));
}

}  // namespace

DeadTimesPage::DeadTimesPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : CamConSectionPage(parent),
      m_session(session),
      m_workspace(workspace),
      m_model(new DeadTimesModel(workspace, this)),
      m_view(new QTableView),
      m_limits(new QLabel) {
    m_view->setModel(m_model);
    m_view->setItemDelegate(new RangeDelegate(m_view));
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setSectionResizeMode(DeadTimesModel::NameColumn,
                                                     QHeaderView::Stretch);
    m_view->setEditTriggers(QAbstractItemView::AllEditTriggers);
    m_view->setAlternatingRowColors(true);

    ReadWriteBar bar([this] { readFromDevice(); }, [this] { writeChanges(); });
    bar.right = {m_limits};
    QHBoxLayout* buttons = readWriteBar(bar);

    auto* layout = new QVBoxLayout(this);
    auto* intro =
        new QLabel(tr("The dead time makes an output switch earlier by the time its "
                      "actuator needs, at every speed. It belongs to the output, not "
                      "to a program."));
    intro->setWordWrap(true);
    layout->addWidget(intro);
    layout->addLayout(buttons);
    layout->addWidget(m_view);

    connect(m_workspace, &Workspace::infoChanged, this, &DeadTimesPage::showLimits);
    showLimits();
}

void DeadTimesPage::showLimits() {
    m_limits->setText(tr("0.1 ms steps, at most %1 (the device's maximum)")
                          .arg(ms(m_workspace->info().maxDeadTime)));
}

void DeadTimesPage::readFromDevice() {
    devicereads::readOutputSettings(
        this, m_session, m_workspace,
        reportRead(
            tr("Reading dead times…"), [] { return tr("Dead times read."); },
            tr("Reading dead times failed: %1")));
}

int DeadTimesPage::itemCount() const {
    return m_workspace->info().deadTimeOutputs + m_workspace->info().outputs;
}

QList<SectionDifference> DeadTimesPage::differences() const {
    QList<SectionDifference> list;
    const CamDocument* cams = m_workspace->cams();
    const QString unknown = tr("not read");
    // Over the device's outputs: dead times where it has them, names on all.
    for (int output = 1; output <= m_workspace->info().outputs; ++output) {
        const std::optional<qint32> deviceTime = cams->deviceDeadTime(output);
        if (output <= m_workspace->info().deadTimeOutputs &&
            cams->deadTime(output) != deviceTime.value_or(0)) {
            list.append({WorkspaceItem::deadTime(output), tr("Output %1 dead time").arg(output),
                         deviceTime ? ms(*deviceTime) : unknown, ms(cams->deadTime(output))});
        }
        const std::optional<QString> deviceName = cams->deviceOutputName(output);
        if (cams->outputName(output) != deviceName.value_or(QString())) {
            list.append({WorkspaceItem::outputName(output), tr("Output %1 name").arg(output),
                         deviceName ? *deviceName : unknown, cams->outputName(output)});
        }
    }
    return list;
}

void DeadTimesPage::writeChanges(std::function<void(const WriteResult&)> done) {
    writeDifferences(m_session, m_workspace, std::move(done));
}

}  // namespace cambench
