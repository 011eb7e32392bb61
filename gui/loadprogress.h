#pragma once
// LoadProgress: the status-bar progress of a program load. Unlike QProgressBar (which repaints
// synchronously on every value change) it only schedules an update, so progress never blocks the
// event loop, even where every repaint is composited through OpenGL.

#include <QWidget>

namespace frezka::gui {

class LoadProgress : public QWidget
{
    Q_OBJECT

public:
    explicit LoadProgress(QWidget *parent = nullptr);
    // fraction 0..1 and what is being done ("Interpreting").
    void setProgress(double fraction, const QString &stage);
    double fraction() const { return m_fraction; }
    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    double m_fraction = 0;
    QString m_stage;
};

} // namespace frezka::gui
