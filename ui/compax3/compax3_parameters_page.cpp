#include "compax3_parameters_page.h"

#include "compax3_gui.h"

#include "comm/compax3/usecases/compax3_parameters.h"
#include "ui/device_session.h"
#include "ui/language.h"
#include "ui/replacement_question.h"
#include "ui/report_dialog.h"
#include "ui/sentence.h"

#include <QCheckBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace cambench {

Compax3ParametersPage::Compax3ParametersPage(DeviceSession* session, Compax3Gui* gui,
                                             QWidget* parent)
    : Compax3Page(session, parent),
      m_gui(gui),
      m_file(new QLabel(tr("No file compared yet."))),
      m_table(new QTableWidget(0, 4)),
      m_force(new QCheckBox(tr("Write to another drive type"))),
      m_store(new QCheckBox(
          tr("Store the written sets in the drive's flash afterwards (1904.n = $32)"))) {
    setObjectName(QStringLiteral("compax3ParametersPage"));
    auto* save = new QPushButton(tr("Save drive to file…"));
    save->setObjectName(QStringLiteral("compax3SaveParameters"));
    connect(save, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(
            this, tr("Save drive parameters"),
            QStringLiteral("compax3-%1.json").arg(facts().identity.serial),
            tr("Compax3 parameter files (*.json)"));
        if (!path.isEmpty()) saveToFile(path);
    });
    auto* compare = new QPushButton(tr("Compare with file…"));
    compare->setObjectName(QStringLiteral("compax3CompareParameters"));
    connect(compare, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Compare with file"), {},
                                                          tr("Compax3 parameter files (*.json)"));
        if (!path.isEmpty()) compareWith(path);
    });
    auto* writeSelected = new QPushButton(tr("Write selected differences…"));
    writeSelected->setObjectName(QStringLiteral("compax3WriteSelected"));
    connect(writeSelected, &QPushButton::clicked, this, [this] { writeFile(true); });
    auto* writeAll = new QPushButton(tr("Write whole file…"));
    writeAll->setObjectName(QStringLiteral("compax3WriteAll"));
    connect(writeAll, &QPushButton::clicked, this, [this] { writeFile(false); });
    m_force->setObjectName(QStringLiteral("compax3Force"));
    m_force->setToolTip(tr("Only when you know the objects mean the same on both drive types."));
    m_store->setObjectName(QStringLiteral("compax3Store"));
    m_table->setObjectName(QStringLiteral("compax3Differences"));
    m_table->setHorizontalHeaderLabels(
        {tr("Object"), tr("Name"), tr("In the file"), tr("On the drive")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_file->setWordWrap(true);

    auto* intro = new QLabel(
        tr("To replace a drive: save the old drive's parameters to a file (or take one saved "
           "before), connect the new drive, compare it with the file, then write the "
           "differences and store the sets."));
    intro->setWordWrap(true);
    auto* row = new QHBoxLayout;
    row->addWidget(save);
    row->addWidget(compare);
    row->addStretch(1);
    auto* writeRow = new QHBoxLayout;
    writeRow->addWidget(writeSelected);
    writeRow->addWidget(writeAll);
    writeRow->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(row);
    layout->addWidget(m_file);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_force);
    layout->addWidget(m_store);
    layout->addLayout(writeRow);
    layout->addWidget(resultLine());
}

void Compax3ParametersPage::saveToFile(const QString& path) {
    if (!facts().known) return;
    const Compax3Dictionary dictionary = m_gui->dictionary();
    const QList<Compax3ObjectId> objects = dictionary.parameters();
    session()->run<comm::Compax3Device, usecases::Compax3Backup>(
        this, tr("Save drive parameters"),
        [objects, dictionary](comm::Compax3Device& device, comm::JobContext& job) {
            return usecases::takeCompax3Parameters(device, objects, dictionary,
                                                   usecases::UseCaseProgress::of(job));
        },
        [this, path](Result<usecases::Compax3Backup> backup) {
            const Status saved =
                backup ? saveCompax3Parameters(path, backup->set) : Status(backup.error());
            if (!saved) {
                ReportDialog::present(
                    window(), QMessageBox::Warning, tr("Save"),
                    tr("No file was saved: %1").arg(asSentence(saved.error().message)));
                return;
            }
            QStringList refused;
            for (const usecases::Compax3Refusal& refusal : backup->refused)
                refused << QStringLiteral("%1: %2").arg(refusal.id.text(), refusal.reason);
            if (!refused.isEmpty()) {
                ReportDialog::present(
                    window(), QMessageBox::Warning, tr("Save"),
                    tr("Saved %1 objects to %2, but the file is incomplete: the drive refused "
                       "%3 objects.")
                        .arg(backup->set.values.size())
                        .arg(path)
                        .arg(refused.size()),
                    refused.join(QLatin1Char('\n')));
                showResult(tr("Incomplete: %1 objects refused.").arg(refused.size()), false);
                return;
            }
            QString text = tr("Saved %1 objects of drive %2 to %3.")
                               .arg(backup->set.values.size())
                               .arg(backup->set.drive.serial, path);
            if (!backup->set.absent.isEmpty()) {
                QStringList absent;
                for (const Compax3ObjectId& id : backup->set.absent) absent << id.text();
                text +=
                    QLatin1Char(' ') + tr("Not on this drive (recorded in the file as absent): %1.")
                                           .arg(absent.join(QStringLiteral(", ")));
            }
            if (!backup->notSaved.isEmpty()) {
                QStringList never;
                for (const usecases::Compax3Refusal& skipped : backup->notSaved)
                    never << skipped.id.text();
                text += QLatin1Char(' ') + tr("Never saved, being control words or functions: %1.")
                                               .arg(never.join(QStringLiteral(", ")));
            }
            showResult(text, true);
        });
}

void Compax3ParametersPage::compareWith(const QString& path) {
    const Result<Compax3ParameterSet> set = loadCompax3Parameters(path);
    if (!set) {
        ReportDialog::present(window(), QMessageBox::Warning, tr("Compare"),
                              asSentence(set.error().message));
        return;
    }
    m_set = *set;
    m_path = path;
    m_file->setText(
        tr("%1: %2 objects of %3 (serial number %4), saved %5.")
            .arg(path)
            .arg(set->values.size())
            .arg(set->drive.info, set->drive.serial,
                 set->taken.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"))));
    m_table->setRowCount(0);
    if (!facts().known) return;
    session()->run<comm::Compax3Device, usecases::Compax3Comparison>(
        this, tr("Compare with file"),
        [s = *set, dictionary = m_gui->dictionary()](comm::Compax3Device& device,
                                                     comm::JobContext& job) {
            return usecases::compareCompax3Parameters(device, s, dictionary,
                                                      usecases::UseCaseProgress::of(job));
        },
        [this](Result<usecases::Compax3Comparison> comparison) {
            if (!comparison) {
                showResult(tr("Not compared: %1").arg(asSentence(comparison.error().message)),
                           false);
                return;
            }
            m_table->setRowCount(int(comparison->differences.size()));
            for (int row = 0; row < comparison->differences.size(); ++row) {
                const usecases::Compax3Difference& d = comparison->differences.at(row);
                const Compax3ObjectInfo* info = m_gui->dictionary().find(d.id);
                auto* object = new QTableWidgetItem(d.id.text());
                object->setFlags(object->flags() | Qt::ItemIsUserCheckable);
                object->setCheckState(Qt::Checked);
                m_table->setItem(row, 0, object);
                m_table->setItem(
                    row, 1,
                    new QTableWidgetItem(info ? info->nameIn(currentLanguage()) : QString()));
                m_table->setItem(row, 2,
                                 new QTableWidgetItem(d.absentInFile ? tr("not on the file's drive")
                                                                     : d.fileValue));
                if (d.absentInFile) {  // nothing in the file to write: no tick
                    object->setFlags(object->flags() & ~Qt::ItemIsUserCheckable);
                    object->setData(Qt::CheckStateRole, QVariant());
                }
                m_table->setItem(row, 3,
                                 new QTableWidgetItem(d.error.isEmpty() ? d.driveValue : d.error));
            }
            const bool otherType = comparison->drive.type() != m_set->drive.type();
            QString text = comparison->differences.isEmpty()
                               ? tr("Equal: the drive holds all %1 values of the file.")
                                     .arg(comparison->compared - comparison->absentOnBoth)
                               : tr("%1 of %2 objects differ.")
                                     .arg(comparison->differences.size())
                                     .arg(comparison->compared);
            if (!comparison->ignored.isEmpty()) {
                QStringList ignored;
                for (const usecases::Compax3Refusal& skipped : comparison->ignored)
                    ignored << skipped.id.text();
                text += QLatin1Char(' ') +
                        tr("Not compared, being control words or functions a file never "
                           "writes: %1.")
                            .arg(ignored.join(QStringLiteral(", ")));
            }
            if (otherType)
                text += QLatin1Char(' ') +
                        tr("The file is from a drive of type %1, this one is of type %2.")
                            .arg(m_set->drive.type(), comparison->drive.type());
            showResult(text, comparison->differences.isEmpty() && !otherType);
        });
}

void Compax3ParametersPage::writeFile(bool selectedOnly) {
    if (!m_set) {
        showResult(tr("Compare with a file first."), false);
        return;
    }
    if (!facts().known) return;
    usecases::Compax3RestoreOptions options;
    options.force = m_force->isChecked();
    options.store = m_store->isChecked();
    if (selectedOnly) {
        for (int row = 0; row < m_table->rowCount(); ++row)
            if (m_table->item(row, 0)->checkState() == Qt::Checked)
                options.only << *parseCompax3Object(m_table->item(row, 0)->text());
        if (options.only.isEmpty()) {
            showResult(tr("No difference is ticked: nothing to write."), false);
            return;
        }
    }
    // Only to the drive the file was read from, or to the one the person
    // accepts as its replacement.
    askRestoreTarget(session(), this, window(), tr("Write"), m_path, m_set->drive.deviceIdentity(),
                     [this, selectedOnly, options](const ReplacementConsent& consent) {
                         usecases::Compax3RestoreOptions accepted = options;
                         accepted.replacement = consent;
                         writeChecked(selectedOnly, accepted);
                     });
}

void Compax3ParametersPage::writeChecked(bool selectedOnly,
                                         const usecases::Compax3RestoreOptions& options) {
    if (!m_set) return;
    const QString what =
        selectedOnly ? tr("%n selected object(s)", nullptr, int(options.only.size()))
                     : tr("the whole file (%n object(s))", nullptr, int(m_set->values.size()));
    if (!confirm(
            tr("Write"),
            tr("Write %1 of %2 to drive %3?").arg(what, m_path, facts().identity.serial),
            tr("The file is checked against the drive first; then only objects that differ "
               "are written, each read back.%1")
                .arg(options.store ? tr(" Afterwards the sets are stored in flash.") : QString())))
        return;
    const Compax3Dictionary dictionary = m_gui->dictionary();
    session()->run<comm::Compax3Device, usecases::OutcomeTally>(
        this, tr("Write parameters"),
        [s = *m_set, dictionary, options](comm::Compax3Device& device, comm::JobContext& job) {
            return usecases::restoreCompax3Parameters(device, s, dictionary, options,
                                                      usecases::UseCaseProgress::of(job));
        },
        [this](Result<usecases::OutcomeTally> tally) {
            if (!tally) {
                ReportDialog::present(window(), QMessageBox::Warning, tr("Write"),
                                      asSentence(tally.error().message));
                showResult(asSentence(tally.error().message), false);
                return;
            }
            ReportDialog::presentTally(window(), tr("Write"), *tally);
            showResult(tally->summary(), tally->complete());
            QList<Compax3ObjectId> touched;
            for (const Compax3ParameterValue& value : m_set->values) touched << value.id;
            Q_EMIT objectsWritten(touched);
            if (!m_path.isEmpty()) compareWith(m_path);
        });
}

void Compax3ParametersPage::factsChanged() {
    if (facts().known) return;
    m_file->setText(tr("No file compared yet."));
    m_table->setRowCount(0);
    m_set.reset();
    m_path.clear();
}

}  // namespace cambench
