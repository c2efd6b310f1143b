#pragma once

#include "model/result.h"

#include <QWidget>

class QAction;
class QComboBox;
class QLabel;
class QLineEdit;
class QTableView;
class QToolBar;
class QVBoxLayout;

namespace cambench {

class CamDiagramWidget;
class CamDocument;
class CamTableModel;
class TrackTableModel;

// The cam program editor page: program chooser and name, track table, cam
// table and diagram, with the editing actions. It edits the CamDocument
// only; reading and writing the device are requests the shell carries out.
class CamEditorWidget : public QWidget {
    Q_OBJECT

public:
    explicit CamEditorWidget(CamDocument* document, QWidget* parent = nullptr);

    CamDocument* document() const { return m_document; }
    CamDiagramWidget* diagram() const { return m_diagram; }
    QTableView* trackTable() const { return m_trackTable; }
    QTableView* camTable() const { return m_camTable; }
    TrackTableModel* trackModel() const { return m_trackModel; }
    CamTableModel* camModel() const { return m_camModel; }

    int currentProgram() const { return m_program; }
    int currentOutput() const;

    // For the shell's Edit menu; they follow the document's undo stack.
    QAction* undoAction() const { return m_undo; }
    QAction* redoAction() const { return m_redo; }
    // Add cam, delete cam, copy…, generate…, import/export, zoom, read/write.
    QList<QAction*> editorActions() const;

    // A bar of the page's own (the timing at speed) put above the diagram.
    void addDiagramBar(QWidget* bar);

    // The CSV work behind the actions, without dialogs (and for tests).
    Status importCsv(const QString& path);
    Status exportCsv(const QString& path) const;

public Q_SLOTS:
    void setCurrentProgram(int program);
    void setCurrentOutput(int output);
    // Online: the read/write actions are enabled only when a device is there.
    void setOnline(bool online);
    void addCam();
    void deleteCam();
    void copyTrack();
    void copyProgram();
    void generateCams();
    void importCsvInteractive();
    void exportCsvInteractive();

Q_SIGNALS:
    void currentProgramChanged(int program);
    void readProgramRequested(int program);
    void writeProgramRequested(int program);

private:
    QAction* makeAction(const QString& text, const QString& tip, void (CamEditorWidget::*slot)());
    QToolBar* createToolBar();
    QWidget* createProgramBar();
    void createTables();
    void refreshProgramChooser();
    void commitProgramName();
    void updateCamActions();
    void selectCam(int output, int cam);
    void showError(const QString& title, const QString& message);

    CamDocument* m_document;
    int m_program = 0;
    bool m_online = false;
    TrackTableModel* m_trackModel;
    CamTableModel* m_camModel;
    QComboBox* m_programChooser = nullptr;
    QLineEdit* m_programName = nullptr;
    QTableView* m_trackTable = nullptr;
    QTableView* m_camTable = nullptr;
    QLabel* m_camTitle = nullptr;
    CamDiagramWidget* m_diagram;
    QVBoxLayout* m_diagramLayout = nullptr;

    QAction* m_undo;
    QAction* m_redo;
    QAction* m_addCam = nullptr;
    QAction* m_deleteCam = nullptr;
    QAction* m_copyTrack = nullptr;
    QAction* m_copyProgram = nullptr;
    QAction* m_generate = nullptr;
    QAction* m_import = nullptr;
    QAction* m_export = nullptr;
    QAction* m_zoomIn = nullptr;
    QAction* m_zoomOut = nullptr;
    QAction* m_zoomFit = nullptr;
    QAction* m_read = nullptr;
    QAction* m_write = nullptr;
};

}  // namespace cambench
