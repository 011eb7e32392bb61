#pragma once
// Z-position monitor: FORM=1 reads the table position on request and sends GO; FORM=2 shows
// the position frames the controller sends by itself.

#include "driver/grinder/zlinksession.h"

#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace frezka::gui {

class ZPositionPanel : public QWidget
{
    Q_OBJECT
public:
    explicit ZPositionPanel(QWidget *parent = nullptr);

    void setSession(grinder::ZLinkSession *session); // nullptr when not in Z mode
    bool readPosition();
    bool goTo(double targetMm);
    QString positionText() const;
    QString statusText() const;

private:
    void onPosition(qint64 positionUm);
    void updateEnabled();

    grinder::ZLinkSession *m_session = nullptr;
    int m_frames = 0;
    int m_skipped = 0;
    QLabel *m_form;
    QLabel *m_position;
    QPushButton *m_readButton;
    QDoubleSpinBox *m_target;
    QPushButton *m_goButton;
    QLabel *m_status;
    QPlainTextEdit *m_log;
};

} // namespace frezka::gui
