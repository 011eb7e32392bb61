#pragma once
// PlacementBar: shown above the toolpath view when the loaded program leaves the machine's
// travel (issue 16 item 7). It says which axis leaves where (the first line) and offers to set
// the work zero in one step: the operator's position stands for a chosen point of the stock
// (the program's X0 Y0, a corner or the centre of its extent; the tool tip on the stock's top,
// the program's Z0), and the bar shows where the program would then sit against the travel;
// or the shift that fits the program inside (session/travelcheck.h). Never modal.

#include "session/stockzero.h"

#include <QFrame>

class QComboBox;
class QLabel;
class QPushButton;

namespace frezka::gui {

class PlacementBar : public QFrame
{
    Q_OBJECT

public:
    explicit PlacementBar(QWidget *parent = nullptr);
    // The loaded program's place (fit at offsets): hides the bar when it is inside the travel.
    void setProgram(const session::TravelFit &fit, const session::OffsetState &offsets,
                    const machine::MachineConfig &config);
    // Where the machine is (the preview follows it); canSet = ready and still.
    void setPosition(const session::Axes4 &machineMm, bool canSet);
    session::StockAnchor anchor() const;
    void setAnchor(session::StockAnchor anchor);
    QString text() const;
    // Where the program would sit with the work zero set here at the chosen point.
    session::Placement preview() const;

signals:
    // The active system's new offset (mm): set here at the chosen point, or fitted inside.
    void workOffsetRequested(const session::Axes4 &offsetMm);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void refresh();
    QString excursionsText() const;

    session::TravelFit m_fit;
    session::OffsetState m_offsets;
    machine::MachineConfig m_config;
    session::Axes4 m_machineMm{};
    bool m_canSet = false;
    QLabel *m_text, *m_anchorLabel, *m_preview;
    QComboBox *m_anchor;
    QPushButton *m_here, *m_fitButton;
};

} // namespace frezka::gui
