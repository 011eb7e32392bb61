#pragma once
// LoadProgress: the status-bar progress of a program load, with its Cancel button. Unlike
// QProgressBar (which repaints synchronously on every value change) the bar only schedules an
// update, so progress never blocks the event loop, even where every repaint is composited
// through OpenGL.

#include <QWidget>

class QToolButton;

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

signals:
    void cancelRequested(); // the operator pressed Cancel

protected:
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    QRect barRect() const;

    QToolButton *m_cancel;
    double m_fraction = 0;
    QString m_stage;
};

} // namespace frezka::gui
