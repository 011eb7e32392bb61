#pragma once
// ProgramInfoDialog: File › Program info (issue 16 item 7) — the loaded program's size, its
// extent (the program's own coordinates and the machine's), the tools in their order with the
// planner's time and the cut length of each, its length and time (session/programinfo.h).
// Non-modal; the main window refreshes it whenever a program is (re)loaded.

#include "session/programinfo.h"

#include <QDialog>

class QLabel;
class QTableWidget;

namespace frezka::gui {

class ProgramInfoDialog : public QDialog
{
    Q_OBJECT

public:
    explicit ProgramInfoDialog(QWidget *parent = nullptr);
    void setInfo(const session::ProgramInfo &info, const QString &fileName);
    QString summary() const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void fill();

    session::ProgramInfo m_info;
    QString m_fileName;
    QLabel *m_summary, *m_extentTitle, *m_toolsTitle;
    QTableWidget *m_extent, *m_tools;
};

} // namespace frezka::gui
