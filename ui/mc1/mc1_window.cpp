#include "mc1_window.h"

#include "mc1_axes_page.h"
#include "mc1_gui.h"
#include "mc1_memory_page.h"
#include "mc1_points_page.h"
#include "mc1_program_page.h"
#include "mc1_trend_page.h"
#include "mc1_variables_page.h"
#include "mc1_watch_model.h"

#include "comm/mc1/usecases/mc1_backup_restore.h"
#include "ui/device_session.h"
#include "ui/main_window.h"
#include "ui/replacement_question.h"
#include "ui/report_dialog.h"
#include "ui/sentence.h"

#include <QFileDialog>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>

namespace cambench {

Mc1Window::Mc1Window(Mc1Gui* gui, MainWindow* window)
    : FactsWindow(gui, window,
                  {Mc1VariablesPage::tr("Read variables"), Mc1PointsPage::tr("Read flags and I/O"),
                   Mc1ProgramPage::tr("Read program status"), Mc1AxesPage::tr("Read axis")}),
      m_mc1(gui),
      m_variables(new Mc1VariablesPage(gui->session(), gui->watchList())),
      m_points(new Mc1PointsPage(gui->session())),
      m_program(new Mc1ProgramPage(gui->session())),
      m_axes(new Mc1AxesPage(gui->session())),
      m_memory(new Mc1MemoryPage(gui->session())),
      m_trend(new Mc1TrendPage(gui->session(), m_variables)) {
    setFactsPages({m_variables, m_points, m_program, m_axes, m_memory, m_trend});
}

void Mc1Window::deviceOnLine(bool load) {
    identifying();
    struct Found {
        Mc1Facts facts;
        QString identity;
    };
    m_mc1->session()->run<comm::Mc1Device, Found>(
        this, tr("Identify controller"),
        [](comm::Mc1Device& device, comm::JobContext&) -> Result<Found> {
            const Result<comm::Mc1Variant> variant = device.ensureIdentified();
            if (!variant) return variant.error();
            Found found;
            // The controller, not its program's state: this line is not polled.
            found.identity = QStringLiteral("%1 (%2)").arg(comm::mc1VariantName(*variant),
                                                           device.variantSource());
            found.facts.known = true;
            found.facts.variant = device.variant();
            found.facts.source = device.variantSource();
            for (comm::Mc1Capability capability :
                 {comm::Mc1Capability::BlockRead, comm::Mc1Capability::MemoryRead,
                  comm::Mc1Capability::MemoryWrite, comm::Mc1Capability::ProgramControl,
                  comm::Mc1Capability::Axes})
                if (device.has(capability)) found.facts.capabilities.insert(capability);
            return found;
        },
        [this, load](Result<Found> found) {
            if (found) setFacts(found->facts);
            identified(load, found ? Result<QString>(found->identity) : found.error(),
                       tr("No MC100/MC200 identified itself: %1"));
        });
}

void Mc1Window::addMenuEntries(const FamilyMenus& menus) {
    QMenu* device = menus.device;
    device->addSeparator();
    QAction* backup = device->addAction(tr("Back up controller (variables, flags)…"), this, [this] {
        const QString path = QFileDialog::getSaveFileName(window(), tr("Back up controller"),
                                                          QStringLiteral("mc1-backup.json"),
                                                          tr("MC-1 backups (*.json)"));
        if (!path.isEmpty()) backupToFile(path);
    });
    backup->setObjectName(QStringLiteral("mc1BackupAction"));
    QAction* verify = device->addAction(tr("Verify controller against backup…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(window(), tr("Verify against backup"), {},
                                                          tr("MC-1 backups (*.json)"));
        if (!path.isEmpty()) verifyFile(path);
    });
    verify->setObjectName(QStringLiteral("mc1VerifyAction"));
    QAction* restore = device->addAction(tr("Restore backup to controller…"), this, [this] {
        const QString path = QFileDialog::getOpenFileName(window(), tr("Restore backup"), {},
                                                          tr("MC-1 backups (*.json)"));
        if (!path.isEmpty()) restoreFile(path);
    });
    restore->setObjectName(QStringLiteral("mc1RestoreAction"));
}

void Mc1Window::backupToFile(const QString& path) {
    m_mc1->session()->run<comm::Mc1Device, Mc1Backup>(
        this, tr("Back up controller"),
        [](comm::Mc1Device& device, comm::JobContext& job) -> Result<Mc1Backup> {
            const Result<comm::Mc1Variant> variant = device.ensureIdentified();
            if (!variant) return variant.error();
            return usecases::takeMc1Backup(device, usecases::defaultMc1BackupScope(*variant),
                                           usecases::UseCaseProgress::of(job));
        },
        [this, path](Result<Mc1Backup> backup) {
            const Status saved = backup ? saveMc1Backup(path, *backup) : Status(backup.error());
            if (!saved) {
                ReportDialog::present(
                    window(), QMessageBox::Warning, tr("Backup"),
                    tr("No backup was saved: %1").arg(asSentence(saved.error().message)));
                return;
            }
            window()->showMessage(tr("Saved %1 variables and %2 flags to %3.")
                                      .arg(backup->variables.size())
                                      .arg(backup->flags.size() * 8)
                                      .arg(path));
        });
}

void Mc1Window::verifyFile(const QString& path) {
    const Result<Mc1Backup> backup = loadMc1Backup(path);
    if (!backup) {
        ReportDialog::present(window(), QMessageBox::Warning, tr("Verify"),
                              asSentence(backup.error().message));
        return;
    }
    m_mc1->session()->run<comm::Mc1Device, usecases::Mc1VerifyReport>(
        this, tr("Verify controller"),
        [b = *backup](comm::Mc1Device& device, comm::JobContext& job) {
            return usecases::verifyMc1Backup(device, b, usecases::UseCaseProgress::of(job));
        },
        [this, path](Result<usecases::Mc1VerifyReport> report) {
            if (!report) {
                ReportDialog::present(
                    window(), QMessageBox::Warning, tr("Verify"),
                    tr("Not verified: %1").arg(asSentence(report.error().message)));
                return;
            }
            const bool equal = report->differences.isEmpty();
            ReportDialog::present(
                window(), equal ? QMessageBox::Information : QMessageBox::Warning, tr("Verify"),
                equal ? tr("The controller holds all %1 values of %2.")
                            .arg(report->compared)
                            .arg(path)
                      : tr("%n difference(s) between the controller and %1:", nullptr,
                           int(report->differences.size()))
                            .arg(path),
                report->differences.join(QLatin1Char('\n')));
        });
}

void Mc1Window::restoreFile(const QString& path) {
    const Result<Mc1Backup> backup = loadMc1Backup(path);
    if (!backup) {
        ReportDialog::present(
            window(), QMessageBox::Warning, tr("Restore"),
            tr("Nothing was written: %1").arg(asSentence(backup.error().message)));
        return;
    }
    // Only to the controller the file was taken from, or to the one the
    // person accepts as its replacement.
    askRestoreTarget(m_mc1->session(), this, window(), tr("Restore"), path, backup->identity,
                     [this, path, b = *backup](const ReplacementConsent& consent) {
                         restoreTo(path, b, consent);
                     });
}

void Mc1Window::restoreTo(const QString& path, const Mc1Backup& backup,
                          const ReplacementConsent& consent) {
    QMessageBox ask(
        QMessageBox::Warning, tr("Restore"),
        tr("Restore %1 (taken %2) to the controller?")
            .arg(path, backup.taken.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"))),
        QMessageBox::Cancel, window());
    ask.setInformativeText(
        tr("It is checked against the controller first; then only the "
           "variables, flags and memory that differ are written. The PLC "
           "program uses them at once."));
    QPushButton* yes = ask.addButton(tr("Restore"), QMessageBox::AcceptRole);
    ask.setDefaultButton(QMessageBox::Cancel);
    ask.exec();
    if (ask.clickedButton() != yes) return;
    m_mc1->session()->run<comm::Mc1Device, usecases::OutcomeTally>(
        this, tr("Restore controller"),
        [backup, consent](comm::Mc1Device& device, comm::JobContext& job) {
            return usecases::restoreMc1Backup(device, backup, consent,
                                              usecases::UseCaseProgress::of(job));
        },
        [this](Result<usecases::OutcomeTally> tally) {
            if (!tally) {
                ReportDialog::present(window(), QMessageBox::Warning, tr("Restore"),
                                      asSentence(tally.error().message));
                return;
            }
            ReportDialog::presentTally(window(), tr("Restore"), *tally);
            if (shownPage()) shownPage()->poll();
        });
}

Mc1Window* mc1Window(const MainWindow* window) {
    return window ? window->findChild<Mc1Window*>() : nullptr;
}

}  // namespace cambench
