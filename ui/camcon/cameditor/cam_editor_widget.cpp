#include "ui/camcon/cameditor/cam_editor_widget.h"

#include "model/camcon/csv_io.h"
#include "model/camcon/data_validation.h"
#include "ui/camcon/cameditor/cam_diagram_widget.h"
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/cam_generator_dialog.h"
#include "ui/camcon/cameditor/cam_table_model.h"
#include "ui/camcon/cameditor/range_delegate.h"
#include "ui/camcon/cameditor/track_table_model.h"

#include <QAction>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QSplitter>
#include <QTableView>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>

namespace cambench {

namespace {
constexpr int kProblemsListed = 5;  // in the message after an import with problems
}

CamEditorWidget::CamEditorWidget(CamDocument* document, QWidget* parent)
    : QWidget(parent),
      m_document(document),
      m_trackModel(new TrackTableModel(document, this)),
      m_camModel(new CamTableModel(document, this)),
      m_diagram(new CamDiagramWidget(document, this)),
      m_undo(document->undoStack()->createUndoAction(this, tr("&Undo"))),
      m_redo(document->undoStack()->createRedoAction(this, tr("&Redo"))) {
    m_undo->setShortcut(QKeySequence::Undo);
    m_redo->setShortcut(QKeySequence::Redo);

    createTables();
    QToolBar* toolBar = createToolBar();  // makes the actions the zoom bar uses too
    auto* tables = new QSplitter(Qt::Horizontal);
    tables->addWidget(m_trackTable);
    auto* camPanel = new QWidget;
    auto* camLayout = new QVBoxLayout(camPanel);
    camLayout->setContentsMargins(0, 0, 0, 0);
    camLayout->addWidget(m_camTitle);
    camLayout->addWidget(m_camTable);
    tables->addWidget(camPanel);
    tables->setStretchFactor(0, 3);
    tables->setStretchFactor(1, 2);

    // Zoom belongs to the diagram: its buttons sit on it, where a narrow
    // window cannot push them into the tool bar's overflow menu.
    auto* diagramPanel = new QWidget;
    auto* diagramLayout = new QVBoxLayout(diagramPanel);
    diagramLayout->setContentsMargins(0, 0, 0, 0);
    diagramLayout->setSpacing(2);
    auto* zoomBar = new QToolBar(diagramPanel);
    zoomBar->setObjectName(QStringLiteral("zoomBar"));
    zoomBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    auto* diagramTitle = new QLabel(tr("Diagram"), zoomBar);
    zoomBar->addWidget(diagramTitle);
    auto* spacer = new QWidget(zoomBar);
    spacer->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    zoomBar->addWidget(spacer);
    zoomBar->addActions({m_zoomIn, m_zoomOut, m_zoomFit});
    diagramLayout->addWidget(zoomBar);
    diagramLayout->addWidget(m_diagram, 1);
    m_diagramLayout = diagramLayout;

    auto* splitter = new QSplitter(Qt::Vertical);
    splitter->addWidget(tables);
    splitter->addWidget(diagramPanel);
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 1);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(toolBar);
    layout->addWidget(createProgramBar());
    layout->addWidget(splitter, 1);

    connect(m_diagram, &CamDiagramWidget::camSelected, this, &CamEditorWidget::selectCam);
    connect(document, &CamDocument::limitsChanged, this, [this] {
        refreshProgramChooser();
        setCurrentProgram(std::clamp(m_program, 0, std::max(m_document->programCount() - 1, 0)));
    });
    connect(document, &CamDocument::programChanged, this, [this](int program) {
        refreshProgramChooser();
        if (program == m_program && !m_programName->hasFocus()) {
            m_programName->setText(m_document->programName(program));
        }
    });
    connect(document, &CamDocument::outputNameChanged, this,
            [this] { setCurrentOutput(currentOutput()); });
    connect(document, &CamDocument::deviceStateChanged, this,
            &CamEditorWidget::refreshProgramChooser);
    refreshProgramChooser();
    setCurrentProgram(0);
    setCurrentOutput(1);
    setOnline(false);
}

QAction* CamEditorWidget::makeAction(const QString& text, const QString& tip,
                                     void (CamEditorWidget::*slot)()) {
    auto* action = new QAction(text, this);
    action->setToolTip(tip);
    action->setStatusTip(tip);
    action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    if (slot) {
        connect(action, &QAction::triggered, this, slot);
    }
    QWidget::addAction(action);
    return action;
}

QToolBar* CamEditorWidget::createToolBar() {
    m_read =
        makeAction(tr("&Read Program"), tr("Read the current program from the device"), nullptr);
    m_write =
        makeAction(tr("&Write Program"), tr("Write the current program to the device"), nullptr);
    m_addCam = makeAction(tr("&Add Cam"), tr("Add a cam to the selected output"),
                          &CamEditorWidget::addCam);
    m_addCam->setShortcut(Qt::CTRL | Qt::Key_N);
    m_deleteCam =
        makeAction(tr("&Delete Cam"), tr("Delete the selected cam"), &CamEditorWidget::deleteCam);
    m_deleteCam->setShortcut(QKeySequence::Delete);
    m_copyTrack = makeAction(tr("Copy &Output To…"),
                             tr("Copy the cams of the selected output to another output"),
                             &CamEditorWidget::copyTrack);
    m_copyProgram =
        makeAction(tr("Copy &Program To…"), tr("Copy the whole program to another program number"),
                   &CamEditorWidget::copyProgram);
    m_generate = makeAction(tr("&Generate Cams…"),
                            tr("Replace the cams of the selected output by evenly spaced cams"),
                            &CamEditorWidget::generateCams);
    m_import =
        makeAction(tr("&Import CSV…"), tr("Replace the cams of this program from a CSV file"),
                   &CamEditorWidget::importCsvInteractive);
    m_export = makeAction(tr("&Export CSV…"), tr("Save the cams of this program as a CSV file"),
                          &CamEditorWidget::exportCsvInteractive);
    m_zoomIn = makeAction(tr("Zoom &In"), tr("Show a smaller part of the axis"), nullptr);
    m_zoomIn->setShortcut(QKeySequence::ZoomIn);
    m_zoomOut = makeAction(tr("Zoom &Out"), tr("Show a larger part of the axis"), nullptr);
    m_zoomOut->setShortcut(QKeySequence::ZoomOut);
    m_zoomFit = makeAction(tr("&Fit"), tr("Show the whole axis IMIN..IMAX"), nullptr);
    connect(m_read, &QAction::triggered, this, [this] { Q_EMIT readProgramRequested(m_program); });
    connect(m_write, &QAction::triggered, this,
            [this] { Q_EMIT writeProgramRequested(m_program); });
    connect(m_zoomIn, &QAction::triggered, m_diagram, &CamDiagramWidget::zoomIn);
    connect(m_zoomOut, &QAction::triggered, m_diagram, &CamDiagramWidget::zoomOut);
    connect(m_zoomFit, &QAction::triggered, m_diagram, &CamDiagramWidget::zoomFit);

    auto* toolBar = new QToolBar(this);
    toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    // Read and Write sit with the program they act on (createProgramBar).
    toolBar->addActions({m_addCam, m_deleteCam, m_generate, m_copyTrack, m_copyProgram});
    toolBar->addSeparator();
    toolBar->addActions({m_import, m_export});
    return toolBar;
}

QWidget* CamEditorWidget::createProgramBar() {
    auto* bar = new QWidget(this);
    auto* layout = new QHBoxLayout(bar);
    layout->setContentsMargins(0, 0, 0, 0);
    m_programChooser = new QComboBox(bar);
    m_programChooser->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_programName = new QLineEdit(bar);
    m_programName->setMaxLength(kMaxNameLength);
    m_programName->setPlaceholderText(tr("no name"));
    auto* programLabel = new QLabel(tr("&Program:"), bar);
    programLabel->setBuddy(m_programChooser);
    auto* nameLabel = new QLabel(tr("&Name:"), bar);
    nameLabel->setBuddy(m_programName);
    layout->addWidget(programLabel);
    layout->addWidget(m_programChooser);
    layout->addSpacing(12);
    layout->addWidget(nameLabel);
    layout->addWidget(m_programName, 1);
    for (QAction* action : {m_read, m_write}) {
        auto* button = new QToolButton(bar);
        button->setDefaultAction(action);
        button->setToolButtonStyle(Qt::ToolButtonTextOnly);
        layout->addWidget(button);
    }
    connect(m_programChooser, &QComboBox::activated, this, &CamEditorWidget::setCurrentProgram);
    connect(m_programName, &QLineEdit::editingFinished, this, &CamEditorWidget::commitProgramName);
    return bar;
}

void CamEditorWidget::createTables() {
    m_trackTable = new QTableView(this);
    m_trackTable->setModel(m_trackModel);
    m_trackTable->setItemDelegate(new RangeDelegate(m_trackTable));
    m_trackTable->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_trackTable->setSelectionMode(QAbstractItemView::SingleSelection);
    m_trackTable->verticalHeader()->hide();
    m_trackTable->horizontalHeader()->setStretchLastSection(true);
    m_trackTable->setWordWrap(false);
    m_trackTable->resizeColumnsToContents();
    // Sized for the longest value, not the (empty) first contents: German
    // decimals ("999,9 ms") must not wrap.
    // ... and never narrower than their (translated) title.
    for (int column : {TrackTableModel::DeadTimeColumn, TrackTableModel::MinimumPulseColumn}) {
        const QString title = m_trackModel->headerData(column, Qt::Horizontal).toString();
        m_trackTable->setColumnWidth(
            column, std::max(fontMetrics().horizontalAdvance(QStringLiteral("00000,0 ms")),
                             fontMetrics().horizontalAdvance(title) + 16));
    }
    m_trackTable->setColumnWidth(TrackTableModel::NameColumn,
                                 fontMetrics().averageCharWidth() * (kMaxNameLength + 2));
    connect(m_trackTable->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) {
                if (current.isValid()) {
                    setCurrentOutput(TrackTableModel::outputForRow(current.row()));
                }
            });

    m_camTitle = new QLabel(this);
    m_camTable = new QTableView(this);
    m_camTable->setModel(m_camModel);
    m_camTable->setItemDelegate(new RangeDelegate(m_camTable));
    m_camTable->setSelectionMode(QAbstractItemView::SingleSelection);
    m_camTable->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_camTable->setEditTriggers(QAbstractItemView::DoubleClicked |
                                QAbstractItemView::EditKeyPressed |
                                QAbstractItemView::AnyKeyPressed);
    connect(m_camTable->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex& current) {
                m_diagram->setSelection(currentOutput(), current.isValid() ? current.row() : -1);
                updateCamActions();
            });
    connect(m_camModel, &QAbstractItemModel::modelReset, this, &CamEditorWidget::updateCamActions);
}

QList<QAction*> CamEditorWidget::editorActions() const {
    return {m_read,        m_write,  m_addCam, m_deleteCam, m_generate, m_copyTrack,
            m_copyProgram, m_import, m_export, m_zoomIn,    m_zoomOut,  m_zoomFit};
}

int CamEditorWidget::currentOutput() const {
    return m_camModel->output();
}

void CamEditorWidget::addDiagramBar(QWidget* bar) {
    m_diagramLayout->insertWidget(m_diagramLayout->indexOf(m_diagram), bar);
}

void CamEditorWidget::setCurrentProgram(int program) {
    const bool changed = program != m_program;
    m_program = program;
    m_trackModel->setProgram(program);
    m_camModel->setTrack(program, currentOutput());
    m_diagram->setProgram(program);
    m_programChooser->setCurrentIndex(program);
    m_programName->setText(m_document->programName(program));
    updateCamActions();
    if (changed) {
        Q_EMIT currentProgramChanged(program);
    }
}

void CamEditorWidget::setCurrentOutput(int output) {
    if (output < 1 || output > m_document->outputCount()) {
        return;
    }
    m_camModel->setTrack(m_program, output);
    const QString name = m_document->outputName(output);
    m_camTitle->setText(name.isEmpty() ? tr("Cams of output %1").arg(output)
                                       : tr("Cams of output %1 (%2)").arg(output).arg(name));
    const int row = TrackTableModel::rowForOutput(output);
    if (m_trackTable->currentIndex().row() != row) {
        m_trackTable->setCurrentIndex(m_trackModel->index(row, TrackTableModel::OutputColumn));
    }
    if (m_diagram->selectedOutput() != output) {
        m_diagram->setSelection(output, -1);
    }
    updateCamActions();
}

void CamEditorWidget::selectCam(int output, int cam) {
    setCurrentOutput(output);
    if (cam >= 0) {
        m_camTable->setCurrentIndex(m_camModel->index(cam, CamTableModel::OnColumn));
    } else {
        m_camTable->setCurrentIndex({});
    }
    m_diagram->setSelection(output, cam);
}

void CamEditorWidget::setOnline(bool online) {
    m_online = online;
    m_read->setEnabled(online);
    m_write->setEnabled(online);
    if (!online) {
        m_diagram->clearLive();
    }
}

void CamEditorWidget::refreshProgramChooser() {
    const QSignalBlocker blocker(m_programChooser);
    const int count = m_document->programCount();
    while (m_programChooser->count() > count) {
        m_programChooser->removeItem(m_programChooser->count() - 1);
    }
    for (int program = 0; program < count; ++program) {
        const QString name = m_document->programName(program);
        QString text =
            name.isEmpty() ? QString::number(program) : tr("%1: %2").arg(program).arg(name);
        // What the device holds there is unknown until it is read.
        if (!m_document->hasDeviceCopy(program)) text = tr("%1 (not read)").arg(text);
        if (program < m_programChooser->count()) {
            m_programChooser->setItemText(program, text);
        } else {
            m_programChooser->addItem(text);
        }
    }
    m_programChooser->setCurrentIndex(m_program);
}

void CamEditorWidget::commitProgramName() {
    const QString name = m_programName->text();
    const QString problem = nameProblem(name);
    if (!problem.isEmpty()) {
        m_programName->setText(m_document->programName(m_program));
        showError(tr("Program Name"), problem);
        return;
    }
    m_document->setProgramName(m_program, name);
}

void CamEditorWidget::updateCamActions() {
    m_deleteCam->setEnabled(m_camTable->currentIndex().isValid());
}

void CamEditorWidget::addCam() {
    const int output = currentOutput();
    const Cam cam = m_document->suggestNewCam(m_program, output);
    m_document->insertCam(m_program, output, cam);
    const int row = int(m_document->track(m_program, output).cams.indexOf(cam));
    selectCam(output, row);
}

void CamEditorWidget::deleteCam() {
    const QModelIndex current = m_camTable->currentIndex();
    if (current.isValid()) {
        m_document->deleteCam(m_program, currentOutput(), current.row());
    }
}

void CamEditorWidget::copyTrack() {
    bool ok = false;
    const int from = currentOutput();
    const int to = QInputDialog::getInt(
        this, tr("Copy Output"),
        tr("Copy the cams of output %1 to output (its cams are replaced):").arg(from),
        from < m_document->outputCount() ? from + 1 : 1, 1, m_document->outputCount(), 1, &ok);
    if (ok && to != from) {
        m_document->copyTrack(m_program, from, m_program, to);
    }
}

void CamEditorWidget::copyProgram() {
    bool ok = false;
    const int last = m_document->programCount() - 1;
    const int to = QInputDialog::getInt(
        this, tr("Copy Program"),
        tr("Copy program %1 to program (its cams and name are replaced):").arg(m_program),
        m_program < last ? m_program + 1 : 0, 0, last, 1, &ok);
    if (ok && to != m_program) {
        m_document->copyProgram(m_program, to);
    }
}

void CamEditorWidget::generateCams() {
    CamGeneratorDialog dialog(m_document, m_program, currentOutput(), this);
    dialog.exec();
}

Status CamEditorWidget::importCsv(const QString& path) {
    Result<Tracks> tracks = loadCamsCsv(path);
    if (!tracks) {
        return tracks.error();
    }
    for (const Track& track : tracks.value()) {
        if (track.output < 1 || track.output > m_document->outputCount()) {
            return Error::invalidData(
                tr("%1: output %2 does not exist; the device has outputs 1..%3. "
                   "Nothing was imported.")
                    .arg(path)
                    .arg(track.output)
                    .arg(m_document->outputCount()));
        }
    }
    m_document->replaceTracks(m_program, tracks.value(),
                              tr("Import cams from %1").arg(QFileInfo(path).fileName()));
    return success();
}

Status CamEditorWidget::exportCsv(const QString& path) const {
    return saveCamsCsv(path, m_document->program(m_program).tracks);
}

void CamEditorWidget::importCsvInteractive() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Import Cams"), {},
                                                      tr("CSV files (*.csv);;All files (*)"));
    if (path.isEmpty()) {
        return;
    }
    const Status status = importCsv(path);
    if (!status) {
        showError(tr("Import Cams"), status.error().message);
        return;
    }
    const QList<CamProblem> problems = validateProgram(
        m_document->program(m_program), m_document->deviceInfo(), m_document->isRotary());
    if (!problems.isEmpty()) {
        QStringList lines;
        for (const CamProblem& problem : problems.mid(0, kProblemsListed)) {
            lines << problem.message;
        }
        QMessageBox::information(
            this, tr("Import Cams"),
            tr("The cams were imported, but %n need fixing before they can be written "
               "(shown in red):\n%1",
               nullptr, int(problems.size()))
                .arg(lines.join(QLatin1Char('\n'))));
    }
}

void CamEditorWidget::exportCsvInteractive() {
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export Cams"), tr("program-%1.csv").arg(m_program),
                                     tr("CSV files (*.csv);;All files (*)"));
    if (path.isEmpty()) {
        return;
    }
    const Status status = exportCsv(path);
    if (!status) {
        showError(tr("Export Cams"), status.error().message);
    }
}

void CamEditorWidget::showError(const QString& title, const QString& message) {
    QMessageBox::warning(this, title, message);
}

}  // namespace cambench
