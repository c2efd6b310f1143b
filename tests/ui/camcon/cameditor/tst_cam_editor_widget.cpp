// The cam editor's widgets on real widgets (offscreen): delegate editing,
// the diagram's geometry and dragging, CSV import and screenshots.
#include "cam_test_support.h"

#include "ui/camcon/cameditor/cam_diagram_widget.h"
#include "ui/camcon/cameditor/cam_editor_widget.h"
#include "ui/camcon/cameditor/cam_generator_dialog.h"
#include "ui/camcon/cameditor/cam_table_model.h"
#include "ui/camcon/cameditor/range_delegate.h"
#include "ui/camcon/cameditor/track_table_model.h"

#include <QAbstractItemModelTester>
#include <QApplication>
#include <QDir>
#include <QSpinBox>
#include <QStyleFactory>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <memory>

using namespace cambench;

namespace {

QPalette darkPalette() {
    QPalette palette;
    const QColor window(45, 45, 48);
    const QColor base(30, 30, 32);
    const QColor text(230, 230, 230);
    palette.setColor(QPalette::Window, window);
    palette.setColor(QPalette::WindowText, text);
    palette.setColor(QPalette::Base, base);
    palette.setColor(QPalette::AlternateBase, QColor(38, 38, 41));
    palette.setColor(QPalette::Text, text);
    palette.setColor(QPalette::Button, window);
    palette.setColor(QPalette::ButtonText, text);
    palette.setColor(QPalette::Highlight, QColor(42, 130, 218));
    palette.setColor(QPalette::HighlightedText, Qt::white);
    palette.setColor(QPalette::Mid, QColor(90, 90, 95));
    palette.setColor(QPalette::ToolTipBase, window);
    palette.setColor(QPalette::ToolTipText, text);
    palette.setColor(QPalette::PlaceholderText, QColor(150, 150, 150));
    return palette;
}

}  // namespace

class CamEditorWidgetTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();

    void delegateEditUpdatesDocumentAndDiagram();
    void undoRestoresDiagramGeometry();
    void wrappingCamIsDrawnAsTwoPieces();
    void hitTestFindsBodyAndEdges();
    void dragMovesCamByExpectedAmountInOneCommand();
    void dragOfEdgeResizesCam();
    void dragOnEmptyAreaPansWhenZoomed();
    void clickInDiagramSelectsCamInTables();
    void addAndDeleteCamActions();
    void generatorDialogProducesCams();
    void csvImportErrorLeavesDocumentUnchanged();
    void csvExportAndImportRoundTrip();
    void screenshotsInLightAndDarkPalette();

private:
    std::unique_ptr<CamDocument> m_document;
    std::unique_ptr<CamEditorWidget> m_editor;
    std::unique_ptr<QAbstractItemModelTester> m_trackTester;
    std::unique_ptr<QAbstractItemModelTester> m_camTester;
};

void CamEditorWidgetTest::initTestCase() {
    // Fusion follows the palette fully, so the dark screenshot is dark.
    QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
}

void CamEditorWidgetTest::init() {
    m_document = std::make_unique<CamDocument>();
    test::loadDemo(*m_document);
    m_editor = std::make_unique<CamEditorWidget>(m_document.get());
    m_trackTester = std::make_unique<QAbstractItemModelTester>(
        m_editor->trackModel(), QAbstractItemModelTester::FailureReportingMode::Fatal);
    m_camTester = std::make_unique<QAbstractItemModelTester>(
        m_editor->camModel(), QAbstractItemModelTester::FailureReportingMode::Fatal);
    m_editor->resize(1000, 700);
    m_editor->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_editor.get()));
}

void CamEditorWidgetTest::cleanup() {
    m_camTester.reset();
    m_trackTester.reset();
    m_editor.reset();
    m_document.reset();
}

void CamEditorWidgetTest::delegateEditUpdatesDocumentAndDiagram() {
    QTableView* table = m_editor->camTable();
    const QModelIndex cell = m_editor->camModel()->index(1, CamTableModel::OnColumn);
    table->setCurrentIndex(cell);
    table->edit(cell);
    auto* editor = qobject_cast<QSpinBox*>(QApplication::focusWidget());
    QVERIFY(editor);
    // The editor takes any digits; the range is checked when it commits.
    QCOMPARE(editor->minimum(), 0);
    QVERIFY(editor->maximum() > 359);
    QCOMPARE(editor->value(), 100);
    editor->setValue(90);
    QTest::keyClick(editor, Qt::Key_Return);

    // The delegate commits through a queued call.
    QTRY_COMPARE(m_document->track(0, 1).cams.at(1), (Cam{90, 150}));
    QCOMPARE(m_document->undoStack()->count(), 1);

    // 3600 is beyond IMAX 359: refused with a word, the editor stays open.
    table->edit(cell);
    editor = qobject_cast<QSpinBox*>(QApplication::focusWidget());
    QVERIFY(editor);
    editor->selectAll();
    QTest::keyClicks(editor, QStringLiteral("3600"));
    QCOMPARE(editor->text(), QStringLiteral("3600"));
    QTest::keyClick(editor, Qt::Key_Return);
    auto* delegate = qobject_cast<RangeDelegate*>(table->itemDelegate());
    QVERIFY(delegate);
    QVERIFY2(delegate->lastRefusal().contains(QStringLiteral("3600")),
             qPrintable(delegate->lastRefusal()));
    QCOMPARE(QApplication::focusWidget(), editor);
    QCOMPARE(m_document->track(0, 1).cams.at(1), (Cam{90, 150}));
    QTest::keyClick(editor, Qt::Key_Escape);
    const QList<QRectF> rects = m_editor->diagram()->camRects(1, 1);
    QCOMPARE(rects.size(), 1);
    const DiagramLayout& layout = m_editor->diagram()->layout();
    QCOMPARE(rects.at(0).left(), layout.xForPosition(90));
    QCOMPARE(rects.at(0).right(), layout.xForPosition(150));
}

void CamEditorWidgetTest::undoRestoresDiagramGeometry() {
    const QRectF before = m_editor->diagram()->camRects(1, 0).value(0);
    QVERIFY(m_editor->camModel()->setData(m_editor->camModel()->index(0, CamTableModel::OffColumn),
                                          80));
    QVERIFY(m_editor->diagram()->camRects(1, 0).value(0).width() > before.width());
    m_editor->undoAction()->trigger();
    QCOMPARE(m_editor->diagram()->camRects(1, 0).value(0), before);
    QCOMPARE(m_editor->camModel()->index(0, CamTableModel::OffColumn).data().toInt(), 60);
    m_editor->redoAction()->trigger();
    QCOMPARE(m_document->track(0, 1).cams.at(0), (Cam{20, 80}));
}

void CamEditorWidgetTest::wrappingCamIsDrawnAsTwoPieces() {
    CamDiagramWidget* diagram = m_editor->diagram();
    const DiagramLayout& layout = diagram->layout();
    const QList<QRectF> rects = diagram->camRects(3, 0);  // 330..30
    QCOMPARE(rects.size(), 2);
    QCOMPARE(rects.at(0).left(), layout.xForPosition(330));
    QCOMPARE(rects.at(0).right(), layout.xForPosition(360));
    QCOMPARE(rects.at(0).right(), double(layout.plotArea().right() + 1));
    QCOMPARE(rects.at(1).left(), double(layout.plotArea().left()));
    QCOMPARE(rects.at(1).right(), layout.xForPosition(30));
    QCOMPARE(rects.at(0).top(), rects.at(1).top());
}

void CamEditorWidgetTest::hitTestFindsBodyAndEdges() {
    CamDiagramWidget* diagram = m_editor->diagram();
    const QRectF bar = diagram->camRects(1, 1).value(0);  // 100..150
    const int y = int(bar.center().y());
    DiagramHit hit = diagram->hitTest(QPoint(int(bar.center().x()), y));
    QCOMPARE(hit.part, DiagramHit::Body);
    QCOMPARE(hit.output, 1);
    QCOMPARE(hit.cam, 1);
    QCOMPARE(diagram->hitTest(QPoint(int(bar.left()) + 1, y)).part, DiagramHit::OnEdge);
    QCOMPARE(diagram->hitTest(QPoint(int(bar.right()) - 1, y)).part, DiagramHit::OffEdge);
    const int empty = int(diagram->layout().xForPosition(250));
    hit = diagram->hitTest(QPoint(empty, y));
    QCOMPARE(hit.part, DiagramHit::Row);
    QCOMPARE(hit.cam, -1);
    // Wrapping cam: its second piece at the left belongs to it as well.
    const QRectF piece = diagram->camRects(3, 0).value(1);
    QCOMPARE(diagram->hitTest(piece.center().toPoint()).cam, 0);
    QCOMPARE(diagram->hitTest(piece.center().toPoint()).output, 3);
}

void CamEditorWidgetTest::dragMovesCamByExpectedAmountInOneCommand() {
    CamDiagramWidget* diagram = m_editor->diagram();
    const DiagramLayout& layout = diagram->layout();
    const QRectF bar = diagram->camRects(1, 1).value(0);  // 100..150
    const QPoint start = bar.center().toPoint();
    const double pixelsPerPosition = 1.0 / layout.positionsPerPixel();
    const QPoint end = start + QPoint(int(std::lround(30 * pixelsPerPosition)), 0);
    const int commands = m_document->undoStack()->count();

    QTest::mousePress(diagram, Qt::LeftButton, Qt::NoModifier, start);
    for (int step = 1; step <= 5; ++step) {
        QTest::mouseMove(diagram, start + (end - start) * step / 5);
    }
    QTest::mouseRelease(diagram, Qt::LeftButton, Qt::NoModifier, end);

    QCOMPARE(m_document->track(0, 1).cams.at(1), (Cam{130, 180}));
    QCOMPARE(m_document->undoStack()->count(), commands + 1);
    QCOMPARE(diagram->camRects(1, 1).value(0).left(), layout.xForPosition(130));
    QCOMPARE(m_editor->camModel()->index(1, CamTableModel::OnColumn).data().toInt(), 130);
    m_document->undoStack()->undo();
    QCOMPARE(m_document->track(0, 1).cams.at(1), (Cam{100, 150}));
}

void CamEditorWidgetTest::dragOfEdgeResizesCam() {
    CamDiagramWidget* diagram = m_editor->diagram();
    const DiagramLayout& layout = diagram->layout();
    const QRectF bar = diagram->camRects(1, 0).value(0);  // 20..60
    const QPoint start(int(std::lround(layout.xForPosition(60))) - 1, int(bar.center().y()));
    QCOMPARE(diagram->hitTest(start).part, DiagramHit::OffEdge);
    // Dragged far beyond IMAX, the off point of a linear axis stops at IMAX.
    DeviceInfo info = test::smallDevice();
    m_document->setLimits(info, false);
    const QPoint end(layout.plotArea().right() + 200, start.y());
    QTest::mousePress(diagram, Qt::LeftButton, Qt::NoModifier, start);
    QTest::mouseMove(diagram, end);
    QTest::mouseRelease(diagram, Qt::LeftButton, Qt::NoModifier, end);
    QCOMPARE(m_document->track(0, 1).cams.at(0), (Cam{20, 359}));
    QCOMPARE(m_document->undoStack()->count(), 1);
}

void CamEditorWidgetTest::dragOnEmptyAreaPansWhenZoomed() {
    CamDiagramWidget* diagram = m_editor->diagram();
    diagram->zoomIn();
    diagram->zoomIn();
    const DiagramLayout& layout = diagram->layout();
    const double startView = layout.viewStart();
    QVERIFY(layout.viewSpan() < 360);
    const QPoint start(layout.plotArea().center().x(), int(layout.rowBand(5).center().y()));
    QCOMPARE(diagram->hitTest(start).part, DiagramHit::Row);
    QTest::mousePress(diagram, Qt::LeftButton, Qt::NoModifier, start);
    QTest::mouseMove(diagram, start + QPoint(50, 0));
    QTest::mouseRelease(diagram, Qt::LeftButton, Qt::NoModifier, start + QPoint(50, 0));
    QVERIFY(layout.viewStart() < startView);
    QCOMPARE(m_document->undoStack()->count(), 0);
    diagram->zoomFit();
    QCOMPARE(layout.viewSpan(), 360.0);
}

void CamEditorWidgetTest::clickInDiagramSelectsCamInTables() {
    CamDiagramWidget* diagram = m_editor->diagram();
    QTest::mouseClick(diagram, Qt::LeftButton, Qt::NoModifier,
                      diagram->camRects(3, 0).value(0).center().toPoint());
    QCOMPARE(m_editor->currentOutput(), 3);
    QCOMPARE(m_editor->trackTable()->currentIndex().row(), 2);
    QCOMPARE(m_editor->camTable()->currentIndex().row(), 0);
    QCOMPARE(diagram->selectedCam(), 0);
    QCOMPARE(m_document->undoStack()->count(), 0);
}

void CamEditorWidgetTest::addAndDeleteCamActions() {
    m_editor->setCurrentOutput(2);
    m_editor->addCam();
    QCOMPARE(m_document->track(0, 2).cams.size(), 1);
    QCOMPARE(m_editor->camTable()->currentIndex().row(), 0);
    QCOMPARE(m_editor->diagram()->camRects(2, 0).size(), 1);
    m_editor->deleteCam();
    QVERIFY(m_document->track(0, 2).cams.isEmpty());
    QCOMPARE(m_document->undoStack()->count(), 2);
}

void CamEditorWidgetTest::generatorDialogProducesCams() {
    CamGeneratorDialog dialog(m_document.get(), 0, 4, m_editor.get());
    CamGeneratorSettings settings;
    settings.mode = CamGeneratorSettings::Mode::CountAndDuty;
    settings.start = 10;
    settings.count = 4;
    settings.dutyPercent = 25;
    dialog.setSettings(settings);
    const Result<Track> preview = dialog.generatedTrack();
    QVERIFY(preview.ok());
    dialog.accept();
    QCOMPARE(m_document->track(0, 4).cams,
             (QList<Cam>{{10, 33}, {100, 123}, {190, 213}, {280, 303}}));
    QCOMPARE(m_document->undoStack()->count(), 1);
    QCOMPARE(m_editor->diagram()->camRects(4, 3).size(), 1);
}

void CamEditorWidgetTest::csvImportErrorLeavesDocumentUnchanged() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("bad.csv"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("output,cam,on,off\n1,1,10,20\n2,1,ten,40\n");
    file.close();
    const CamProgram before = m_document->program(0);

    const Status status = m_editor->importCsv(path);
    QVERIFY(!status.ok());
    QVERIFY2(status.error().message.contains(QStringLiteral("Line 3")),
             qPrintable(status.error().message));
    QCOMPARE(m_document->program(0), before);
    QCOMPARE(m_document->undoStack()->count(), 0);

    // An output the device does not have is refused as a whole too.
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write("output,cam,on,off\n1,1,10,20\n9,1,30,40\n");
    file.close();
    QVERIFY(!m_editor->importCsv(path).ok());
    QCOMPARE(m_document->program(0), before);
}

void CamEditorWidgetTest::csvExportAndImportRoundTrip() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("program.csv"));
    QVERIFY(m_editor->exportCsv(path).ok());
    const CamProgram exported = m_document->program(0);
    m_document->deleteCam(0, 1, 0);
    QVERIFY(m_editor->importCsv(path).ok());
    QCOMPARE(m_document->program(0), exported);
    QCOMPARE(m_document->undoStack()->count(), 2);
}

void CamEditorWidgetTest::screenshotsInLightAndDarkPalette() {
    // A busier demo: names, dead times, an edited cam, an overlap and live data.
    m_document->loadOutputSettingsFromDevice({{1, QStringLiteral("Glue valve")},
                                              {2, QStringLiteral("Knife")},
                                              {3, QStringLiteral("Wrap sensor")}},
                                             {{1, 25}, {2, 123}});
    m_document->insertCam(0, 2, {200, 260});
    m_document->insertCam(0, 5, {40, 90});
    m_document->insertCam(0, 5, {80, 120});  // overlaps the one before
    m_editor->setOnline(true);
    m_editor->diagram()->setLivePosition(140);
    m_editor->diagram()->setOutputStates({true, false, true, false, false, false, false, false});
    m_editor->setCurrentOutput(1);
    m_editor->camTable()->setCurrentIndex(m_editor->camModel()->index(1, CamTableModel::OnColumn));

    const QByteArray directory = qgetenv("CAMBENCH_SCREENSHOT_DIR");
    const QPalette light = QApplication::style()->standardPalette();
    for (const auto& [name, palette] : {std::pair{QStringLiteral("light"), light},
                                        std::pair{QStringLiteral("dark"), darkPalette()}}) {
        m_editor->setPalette(palette);
        const QImage image = m_editor->grab().toImage();
        QVERIFY(!image.isNull());
        // The diagram paints from the palette: its background follows it.
        const QPoint corner = m_editor->diagram()->mapTo(m_editor.get(), QPoint(2, 2));
        QCOMPARE(image.pixelColor(corner), palette.color(QPalette::Window));
        if (!directory.isEmpty()) {
            QDir().mkpath(QString::fromLocal8Bit(directory));
            const QString file = QDir(QString::fromLocal8Bit(directory))
                                     .filePath(QStringLiteral("cam-editor-%1.png").arg(name));
            QVERIFY2(image.save(file), qPrintable(file));
        }
    }
}

QTEST_MAIN(CamEditorWidgetTest)
#include "tst_cam_editor_widget.moc"
