#include "programlisting.h"

#include <QContextMenuEvent>
#include <QFontDatabase>
#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>

namespace frezka::gui {

ProgramListing::ProgramListing(QWidget *parent)
    : QAbstractScrollArea(parent)
{
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setFocusPolicy(Qt::StrongFocus);
    viewport()->setBackgroundRole(QPalette::Base);
    viewport()->setAutoFillBackground(true);
    connect(verticalScrollBar(), &QScrollBar::valueChanged, viewport(),
            qOverload<>(&QWidget::update));
    connect(horizontalScrollBar(), &QScrollBar::valueChanged, viewport(),
            qOverload<>(&QWidget::update));
}

int ProgramListing::lineHeight() const
{
    return fontMetrics().height() + 1;
}

int ProgramListing::visibleLines() const
{
    return std::max(1, viewport()->height() / lineHeight());
}

int ProgramListing::firstVisibleLine() const
{
    return verticalScrollBar()->value() + 1;
}

void ProgramListing::updateScrollBars()
{
    verticalScrollBar()->setRange(0, std::max(0, lineCount() - visibleLines()));
    verticalScrollBar()->setPageStep(visibleLines());
    horizontalScrollBar()->setRange(0, 40 * fontMetrics().horizontalAdvance(QLatin1Char('0')));
    horizontalScrollBar()->setPageStep(viewport()->width());
}

void ProgramListing::setText(std::shared_ptr<const ProgramText> text)
{
    m_text = std::move(text);
    m_current = 0;
    m_selected = 0;
    m_errors.clear();
    updateScrollBars();
    verticalScrollBar()->setValue(0);
    viewport()->update();
}

void ProgramListing::centreOn(int line)
{
    const int first = verticalScrollBar()->value() + 1;
    const int n = visibleLines();
    if (line < first + 2 || line > first + n - 3)
        verticalScrollBar()->setValue(line - 1 - n / 2);
}

void ProgramListing::showCurrentLine(int line)
{
    if (line == m_current)
        return;
    m_current = line;
    if (line > 0 && line <= lineCount())
        centreOn(line);
    viewport()->update();
}

void ProgramListing::setErrorLines(std::set<int> lines)
{
    m_errors = std::move(lines);
    viewport()->update();
}

void ProgramListing::showErrorLine(int line)
{
    if (line <= 0 || line > lineCount())
        return;
    m_selected = line;
    centreOn(line);
    viewport()->update();
}

void ProgramListing::resizeEvent(QResizeEvent *event)
{
    QAbstractScrollArea::resizeEvent(event);
    updateScrollBars();
}

void ProgramListing::paintEvent(QPaintEvent *)
{
    QPainter p(viewport());
    if (!m_text)
        return;
    const int h = lineHeight();
    const int first = verticalScrollBar()->value();
    const int last = std::min(lineCount(), first + visibleLines() + 1);
    const int digits = int(QString::number(lineCount()).size());
    const int gutter = fontMetrics().horizontalAdvance(QLatin1Char('0')) * (digits + 1);
    const int dx = horizontalScrollBar()->value();
    const QPalette &pal = palette();
    for (int i = first; i < last; ++i) {
        const int line = i + 1;
        const QRect row(0, (i - first) * h, viewport()->width(), h);
        QColor text = pal.color(QPalette::Text);
        if (line == m_current) {
            p.fillRect(row, QColor(255, 220, 80));
            text = Qt::black;
        } else if (m_errors.count(line)) {
            p.fillRect(row, QColor(255, 150, 150));
            text = Qt::black;
        } else if (line == m_selected) {
            p.fillRect(row, pal.color(QPalette::Highlight));
            text = pal.color(QPalette::HighlightedText);
        }
        p.setPen(QColor(130, 130, 130));
        p.drawText(QRect(0, row.top(), gutter - 4, h), Qt::AlignRight | Qt::AlignVCenter,
                   QString::number(line));
        p.setPen(text);
        p.setClipRect(QRect(gutter, row.top(), viewport()->width() - gutter, h));
        p.drawText(QRect(gutter + 4 - dx, row.top(), 100000, h), Qt::AlignLeft | Qt::AlignVCenter,
                   m_text->line(i));
        p.setClipping(false);
    }
}

int ProgramListing::lineAt(int y) const
{
    const int line = verticalScrollBar()->value() + 1 + y / lineHeight();
    return line >= 1 && line <= lineCount() ? line : 0;
}

void ProgramListing::contextMenuEvent(QContextMenuEvent *event)
{
    const int line = lineAt(event->pos().y()); // viewport coordinates, as the mouse's
    if (line == 0)
        return;
    m_selected = line;
    viewport()->update();
    QMenu menu(this);
    menu.addAction(tr("Run from this line (%1)…").arg(line), this,
                   [this, line] { emit runFromLineRequested(line); });
    menu.exec(event->globalPos());
}

void ProgramListing::mousePressEvent(QMouseEvent *event)
{
    const int line = lineAt(int(event->position().y()));
    if (line != 0) {
        m_selected = line;
        viewport()->update();
        emit lineClicked(line);
    }
}

void ProgramListing::keyPressEvent(QKeyEvent *event)
{
    switch (event->key()) {
    case Qt::Key_Home:
        verticalScrollBar()->setValue(0);
        break;
    case Qt::Key_End:
        verticalScrollBar()->setValue(verticalScrollBar()->maximum());
        break;
    default:
        QAbstractScrollArea::keyPressEvent(event);
    }
}

} // namespace frezka::gui
