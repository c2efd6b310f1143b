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

    QSize sizeHint() const override;
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    int columns(int width) const;

    QList<bool> m_states;
};

}  // namespace cambench
