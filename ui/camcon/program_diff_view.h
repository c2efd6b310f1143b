#pragma once

#include "model/camcon/cam_axis.h"
#include "model/camcon/program_diff.h"

#include <QMap>
#include <QWidget>

class QCheckBox;
class QLayout;
class QListWidget;
class QSplitter;
class QPainter;

namespace cambench {

// Two cam programs drawn one over the other, a row per output: cams the
// same in both in grey; a changed cam's old extent (A) as a dashed ghost
// with the new one (B) solid over it and its moved edges marked; a cam only
// in A hatched, one only in B cross-hatched. Shape tells them apart as well
// as colour, in light and dark palettes. A click on a difference selects it.
class ProgramDiffView : public QWidget {
    Q_OBJECT
public:
    explicit ProgramDiffView(QWidget* parent = nullptr);

    void setComparison(const CamProgram& a, const CamProgram& b, const ProgramDiff& diff,
                       const Axis& axis, const QMap<int, QString>& outputNames);
    // Outputs without a difference fold away.
    void setFoldUnchanged(bool fold);
    QList<int> shownOutputs() const { return m_outputs; }
    // An index into the diff's cams, -1 for none.
    void setSelected(int difference);
    int selected() const { return m_selected; }

    // The swatches of the legend, as the diagram draws them.
    enum class Swatch { Same, Changed, OnlyInA, OnlyInB };
    static void paintSwatch(QPainter& painter, const QRectF& rect, Swatch swatch,
                            const QPalette& palette);
    // The diagram's legend in a row: each swatch and what it means.
    static QLayout* legend(const QPalette& palette);
    // `view` in a scroll area beside `list` (the differences it draws, in
    // its order), a click on either selecting the difference in both, and
    // `fold` hiding the outputs without one: as every comparison shows it.
    static QSplitter* besideList(ProgramDiffView* view, QListWidget* list, QCheckBox* fold);

    QSize sizeHint() const override;

Q_SIGNALS:
    void differenceClicked(int difference);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void layoutRows();
    // Where difference `index` is drawn (for hits and the selection frame).
    QList<QRectF> differenceRects(int index) const;
    QRect plotArea() const;

    CamProgram m_a;
    CamProgram m_b;
    ProgramDiff m_diff;
    Axis m_axis;
    QMap<int, QString> m_names;
    bool m_fold = false;
    QList<int> m_outputs;  // the rows, in order
    int m_selected = -1;
};

}  // namespace cambench
