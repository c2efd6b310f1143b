#pragma once

#include "model/camcon/cam_program.h"
#include "model/camcon/cam_timing.h"
#include "ui/camcon/cameditor/diagram_layout.h"

#include <QList>
#include <QWidget>

class QScrollBar;

namespace cambench {

class CamDocument;

// What lies under a point of the diagram.
struct DiagramHit {
    enum Part { Nothing, Row, Body, OnEdge, OffEdge };
    Part part = Nothing;
    int output = 0;  // 1-based, 0 when none
    int cam = -1;    // index in the track, -1 when none
};

// All tracks of one program as bars over IMIN..IMAX with a scale. Drag a
// bar to move the cam, drag an edge to move one point (one undo command per
// drag); drag empty space or use the scroll bars to pan; Ctrl+wheel and
// +/- zoom. Live cursor and output LEDs when the shell feeds them.
class CamDiagramWidget : public QWidget {
    Q_OBJECT

public:
    explicit CamDiagramWidget(CamDocument* document, QWidget* parent = nullptr);

    int program() const { return m_program; }
    int selectedOutput() const { return m_selectedOutput; }
    int selectedCam() const { return m_selectedCam; }

    // Geometry in widget coordinates (also what the tests check).
    const DiagramLayout& layout() const { return m_layout; }
    QList<QRectF> camRects(int output, int index) const;
    DiagramHit hitTest(const QPoint& point) const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

public Q_SLOTS:
    void setProgram(int program);
    void setSelection(int output, int cam);
    void zoomIn();
    void zoomOut();
    void zoomFit();
    void setLivePosition(qint32 position);
    void setOutputStates(const QList<bool>& states);
    void clearLive();
    bool isLive() const { return m_live; }
    // Where the outputs switch electrically at a speed: a strip under each
    // row with the on-times, each cam's duration, and the problems marked
    // at the row's label. `speed` names the speed for tool tips.
    void setTiming(const QList<OutputTiming>& outputs, const QString& speed);
    void clearTiming();

public:
    bool timingShown() const { return m_timingShown; }
    // The strip pieces of an output's electrical cam (tests check them).
    QList<QRectF> timingRects(int output, int cam) const;

Q_SIGNALS:
    // The user clicked a cam (cam >= 0) or an empty part of a row (cam = -1).
    void camSelected(int output, int cam);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    bool event(QEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    enum class Drag { None, Cam, OnEdge, OffEdge, Pan };

    void updateLayout();
    void syncScrollBars();
    void ensureOutputVisible(int output);
    void dragCamTo(double position);
    int labelWidth() const;
    int rowHeight() const;
    int stripHeight() const;
    int scaleHeight() const;
    QString camToolTip(int output, int cam) const;

    void paintScale(QPainter& painter) const;
    void paintRows(QPainter& painter) const;
    void paintCams(QPainter& painter, int output) const;
    void paintLabel(QPainter& painter, int output) const;
    void paintLiveCursor(QPainter& painter) const;
    void paintTiming(QPainter& painter, int output) const;
    QString timingToolTip(int output, int cam) const;
    QString timingToolTipAt(const QPoint& point) const;

    CamDocument* m_document;
    DiagramLayout m_layout;
    QScrollBar* m_horizontal;
    QScrollBar* m_vertical;
    int m_program = 0;
    int m_selectedOutput = 1;
    int m_selectedCam = -1;

    bool m_live = false;
    qint32 m_livePosition = 0;
    QList<bool> m_outputStates;

    bool m_timingShown = false;
    QMap<int, OutputTiming> m_timing;  // key = output
    QString m_timingSpeed;

    Drag m_drag = Drag::None;
    int m_dragOutput = 0;
    int m_dragCam = -1;
    Cam m_dragOrigin;
    double m_pressPosition = 0;
    double m_pressViewStart = 0;
    quint64 m_dragKey = 0;
};

}  // namespace cambench
