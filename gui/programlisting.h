#pragma once
// ProgramListing: the program text with line numbers, the line being cut highlighted and
// error lines marked. A uniform-height list view over ProgramText, so it scrolls millions of
// lines without laying them out.

#include "programtext.h"

#include <QAbstractListModel>
#include <QListView>

#include <memory>
#include <set>

namespace frezka::gui {

class ProgramListModel : public QAbstractListModel
{
    Q_OBJECT

public:
    using QAbstractListModel::QAbstractListModel;
    void setText(std::shared_ptr<const ProgramText> text);
    // 1-based source line currently executing (0 = none).
    void setCurrentLine(int line);
    int currentLine() const { return m_current; }
    void setErrorLines(std::set<int> lines);

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;

private:
    std::shared_ptr<const ProgramText> m_text;
    int m_current = 0;
    std::set<int> m_errors;
};

class ProgramListing : public QListView
{
    Q_OBJECT

public:
    explicit ProgramListing(QWidget *parent = nullptr);
    ProgramListModel *listModel() const { return m_model; }
    // Highlights and scrolls to a 1-based line (unless the user scrolled away recently).
    void showCurrentLine(int line);
    void showErrorLine(int line);

private:
    ProgramListModel *m_model;
};

} // namespace frezka::gui
