#pragma once
// ProgramListing: the program text with line numbers, the line being cut highlighted and error
// lines marked. It paints only the visible lines straight from ProgramText and keeps nothing
// per line (item views keep per-row layout or header data), so a file of millions of lines
// opens and scrolls at once.

#include "programview.h"

#include <QAbstractScrollArea>

#include <memory>
#include <set>

namespace frezka::gui {

class ProgramListing : public QAbstractScrollArea
{
    Q_OBJECT

public:
    explicit ProgramListing(QWidget *parent = nullptr);
    void setText(std::shared_ptr<const ProgramText> text);
    int lineCount() const { return m_text ? m_text->lineCount() : 0; }
    // 1-based line executing now (0 = none): highlighted and kept in view.
    void showCurrentLine(int line);
    int currentLine() const { return m_current; }
    void setErrorLines(std::set<int> lines);
    // Scrolls to and selects a 1-based line (an error).
    void showErrorLine(int line);
    int selectedLine() const { return m_selected; }
    int firstVisibleLine() const; // 1-based

signals:
    void lineClicked(int line);
    // The context menu's "Run from this line…" on a 1-based line.
    void runFromLineRequested(int line);

protected:
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;

private:
    int lineHeight() const;
    int lineAt(int y) const; // 1-based line at a viewport y, 0 = none
    int visibleLines() const;
    void updateScrollBars();
    void centreOn(int line);

    std::shared_ptr<const ProgramText> m_text;
    int m_current = 0;
    int m_selected = 0;
    std::set<int> m_errors;
};

} // namespace frezka::gui
