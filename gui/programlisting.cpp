#include "programlisting.h"

#include <QBrush>
#include <QFontDatabase>
#include <QPalette>

namespace frezka::gui {

void ProgramListModel::setText(std::shared_ptr<const ProgramText> text)
{
    beginResetModel();
    m_text = std::move(text);
    m_current = 0;
    m_errors.clear();
    endResetModel();
}

void ProgramListModel::setCurrentLine(int line)
{
    if (line == m_current)
        return;
    const int old = m_current;
    m_current = line;
    if (old > 0 && old <= rowCount())
        emit dataChanged(index(old - 1), index(old - 1));
    if (line > 0 && line <= rowCount())
        emit dataChanged(index(line - 1), index(line - 1));
}

void ProgramListModel::setErrorLines(std::set<int> lines)
{
    m_errors = std::move(lines);
    if (rowCount() > 0)
        emit dataChanged(index(0), index(rowCount() - 1));
}

int ProgramListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() || !m_text ? 0 : m_text->lineCount();
}

QVariant ProgramListModel::data(const QModelIndex &index, int role) const
{
    if (!m_text || !index.isValid())
        return {};
    const int line = index.row() + 1;
    switch (role) {
    case Qt::DisplayRole:
        return QStringLiteral("%1  %2").arg(line, 7).arg(m_text->line(index.row()));
    case Qt::BackgroundRole:
        if (line == m_current)
            return QBrush(QColor(255, 220, 80));
        if (m_errors.count(line))
            return QBrush(QColor(255, 150, 150));
        return {};
    case Qt::ForegroundRole:
        if (line == m_current || m_errors.count(line))
            return QBrush(Qt::black);
        return {};
    default:
        return {};
    }
}

ProgramListing::ProgramListing(QWidget *parent)
    : QListView(parent)
    , m_model(new ProgramListModel(this))
{
    setModel(m_model);
    setUniformItemSizes(true);
    setLayoutMode(QListView::SinglePass);
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setSelectionMode(QAbstractItemView::SingleSelection);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
}

void ProgramListing::showCurrentLine(int line)
{
    m_model->setCurrentLine(line);
    if (line > 0 && line <= m_model->rowCount())
        scrollTo(m_model->index(line - 1), QAbstractItemView::PositionAtCenter);
}

void ProgramListing::showErrorLine(int line)
{
    if (line > 0 && line <= m_model->rowCount()) {
        const QModelIndex idx = m_model->index(line - 1);
        scrollTo(idx, QAbstractItemView::PositionAtCenter);
        setCurrentIndex(idx);
    }
}

} // namespace frezka::gui
