#pragma once

#include <QWidget>

namespace cambench {

// A row-wrapped strip of numbered LEDs (outputs or inputs, counting from 1).
// Lit LEDs use the palette's highlight colour so they stay visible in the
// light and the dark palette.
class LedStrip : public QWidget {
    Q_OBJECT
public:
    explicit LedStrip(QWidget* parent = nullptr);

    void setStates(const QList<bool>& states);
    void setCount(int count);
    const QList<bool>& states() const { return m_states; }
    // The number under each LED (default: 1, 2, 3, ...), e.g. flags M2000–.
    void setNumbers(const QList<int>& numbers);
    // Stale values are drawn hollow and grey: what they showed is no longer
    // known to be true.
    void setStale(bool stale);
    bool isStale() const { return m_stale; }
    // The LED at `point`, -1 for none.
    int indexAt(const QPoint& point) const;

Q_SIGNALS:
    void ledClicked(int index);

public:
    QSize sizeHint() const override;
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override;

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;

private:
    int columns(int width) const;

    QList<bool> m_states;
    QList<int> m_numbers;
    bool m_stale = false;
};

}  // namespace cambench
