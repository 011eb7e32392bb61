#pragma once
// LedWidget: a small round lamp with a caption, like the unit's own LEDs.

#include <QColor>
#include <QWidget>

namespace frezka::gui {

class LedWidget : public QWidget
{
    Q_OBJECT

public:
    explicit LedWidget(const QString &caption, QColor onColour = QColor(40, 220, 60),
                       QWidget *parent = nullptr);
    void setOn(bool on);
    bool isOn() const { return m_on; }
    void setCaption(const QString &caption);
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override { return sizeHint(); } // never cut the caption

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    QString m_caption;
    QColor m_onColour;
    bool m_on = false;
};

} // namespace frezka::gui
