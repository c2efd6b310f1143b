#include "dead_times_page.h"

#include "dead_times_model.h"
#include "device_session.h"
#include "workspace.h"

#include "ui/cameditor/cam_document.h"
#include "ui/cameditor/range_delegate.h"

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

namespace cambench {

namespace {

struct OutputSettings {
    QMap<int, QString> names;
    DeadTimes deadTimes;
};

QString ms(qint32 tenths) {
    return QCoreApplication::translate("cambench::DeadTimesModel", "%1 ms")
        .arg(QLocale().toString(tenths / 10.0, 'f', 1));
}

}  // namespace

DeadTimesPage::DeadTimesPage(DeviceSession* session, Workspace* workspace, QWidget* parent)
    : SectionPage(parent),
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

    auto* read = new QPushButton(tr("Read from device"));
    auto* write = new QPushButton(tr("Write changes"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(read);
    buttons->addWidget(write);
    buttons->addStretch();
    buttons->addWidget(m_limits);

    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("The dead time makes an output switch earlier by the time its "
                                "actuator needs, at every speed. It belongs to the output, not "
                                "to a program."));
    intro->setWordWrap(true);
    layout->addWidget(intro);
    layout->addLayout(buttons);
    layout->addWidget(m_view);

    connect(read, &QPushButton::clicked, this, &DeadTimesPage::readFromDevice);
    connect(write, &QPushButton::clicked, this, [this] {
        writeItems({}, [this](const WriteReport& report) {
            Q_EMIT statusMessage(tr("Dead times: %1").arg(report.summary()));
            if (!report.complete())
                QMessageBox::warning(this, tr("Dead times"), report.details());
        });
    });
    connect(m_workspace, &Workspace::infoChanged, this, &DeadTimesPage::showLimits);
    showLimits();
}

void DeadTimesPage::showLimits() {
    m_limits->setText(tr("0.1 ms steps, at most %1 (?GTZKMAX)").arg(ms(m_workspace->info().maxDeadTime)));
}

void DeadTimesPage::deviceConnected() { readFromDevice(); }

void DeadTimesPage::readFromDevice() {
    const int outputs = m_workspace->info().deadTimeOutputs;
    Q_EMIT statusMessage(tr("Reading dead times…"));
    m_session->run<OutputSettings>(
        this, tr("Read dead times"),
        [outputs](comm::CamConDevice& client, comm::JobContext& job) -> Result<OutputSettings> {
            OutputSettings settings;
            auto deadTimes = client.readDeadTimes(outputs);
            if (!deadTimes) return deadTimes.error();
            settings.deadTimes = deadTimes.value();
            // The table interface has no output names: the dead times are all there is.
            if (!client.has(comm::CamConCapability::OutputNames)) return settings;
            for (int output = 1; output <= outputs; ++output) {
                if (job.cancelled()) return Error::cancelled();
                job.progress(output, outputs);
                auto name = client.readOutputName(output);
                if (!name) return name.error();
                settings.names.insert(output, name.value());
            }
            return settings;
        },
        [this](Result<OutputSettings> result) {
            if (!result) {
                Q_EMIT statusMessage(tr("Reading dead times failed: %1").arg(result.error().message));
                return;
            }
            m_workspace->loadOutputSettingsFromDevice(result->names, result->deadTimes);
            Q_EMIT statusMessage(tr("Dead times read."));
        });
}

QList<SectionDifference> DeadTimesPage::differences() const {
    QList<SectionDifference> list;
    const CamDocument* cams = m_workspace->cams();
    const bool known = m_workspace->outputSettingsKnown();
    const QString unknown = tr("not read");
    for (int output = 1; output <= m_workspace->info().outputs; ++output) {
        if (output <= m_workspace->info().deadTimeOutputs &&
            (!known || cams->deadTime(output) != m_workspace->deviceDeadTime(output))) {
            list.append({QStringLiteral("tzk:%1").arg(output),
                         tr("Output %1 dead time").arg(output),
                         known ? ms(m_workspace->deviceDeadTime(output)) : unknown,
                         ms(cams->deadTime(output))});
        }
        if (cams->outputName(output) != m_workspace->deviceOutputName(output) ||
            (!known && !cams->outputName(output).isEmpty())) {
            list.append({QStringLiteral("name:%1").arg(output), tr("Output %1 name").arg(output),
                         known ? m_workspace->deviceOutputName(output) : unknown,
                         cams->outputName(output)});
        }
    }
    return list;
}

void DeadTimesPage::writeItems(const QStringList& keys,
                               std::function<void(const WriteReport&)> done) {
    const QList<SectionDifference> all = differences();
    struct Item {
        QString key;
        QString label;
        int output;
        bool isName;
        qint32 deadTime;
        QString name;
    };
    QList<Item> items;
    for (const SectionDifference& difference : all) {
        if (!keys.isEmpty() && !keys.contains(difference.key)) continue;
        const int output = difference.key.section(QLatin1Char(':'), 1).toInt();
        const bool isName = difference.key.startsWith(QLatin1String("name:"));
        items.append({difference.key, difference.item, output, isName,
                      m_workspace->cams()->deadTime(output), m_workspace->cams()->outputName(output)});
    }
    WriteReport base;
    // Selected items that already match, or (write all) every output that does.
    base.unchanged = keys.isEmpty() ? m_workspace->info().deadTimeOutputs * 2 - int(all.size())
                                    : int(keys.size() - items.size());
    if (base.unchanged < 0) base.unchanged = 0;
    m_session->run<ItemOutcomes>(
        this, tr("Write dead times"),
        [items](comm::CamConDevice& client, comm::JobContext& job) -> Result<ItemOutcomes> {
            ItemOutcomes outcomes;
            int n = 0;
            for (const Item& item : items) {
                job.progress(n++, items.size());
                if (job.cancelled()) {
                    outcomes.append({item.key, item.label, Error::cancelled()});
                    continue;
                }
                const Status status = item.isName ? client.writeOutputName(item.output, item.name)
                                                  : client.writeDeadTime(item.output, item.deadTime);
                outcomes.append({item.key, item.label, status ? Error{} : status.error()});
            }
            return outcomes;
        },
        [this, base, done](Result<ItemOutcomes> outcomes) {
            WriteReport report = base;
            report.add(outcomes.value());
            QList<int> deadTimes;
            QList<int> names;
            for (const ItemOutcome& outcome : outcomes.value()) {
                if (outcome.error.kind != ErrorKind::None) continue;
                const int output = outcome.key.section(QLatin1Char(':'), 1).toInt();
                (outcome.key.startsWith(QLatin1String("name:")) ? names : deadTimes) << output;
            }
            m_workspace->markOutputSettingsWritten(deadTimes, names);
            done(report);
        });
}

}  // namespace cambench
