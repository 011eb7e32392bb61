#pragma once
// Machine › Tool table: the profile's tool table (LinuxCNC .tbl, gcode/tooltable.h) as a grid
// of tool number, pocket, length (Z), diameter and comment; add, remove, edit, save. Saving
// checks every row first (a row that cannot be read is named with what to fix, nothing is
// written) and writes the file atomically. The other words of a line (X Y A offsets, lathe
// angles, orientation) are kept as they were read.

#include "gcode/tooltable.h"

#include <QDialog>

#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace frezka::gui {

class ToolTableDialog : public QDialog
{
    Q_OBJECT

public:
    enum Column { ToolColumn, PocketColumn, LengthColumn, DiameterColumn, CommentColumn };

    // path: the table file (created by the first save when it does not exist).
    explicit ToolTableDialog(const QString &path, QWidget *parent = nullptr);

    QString path() const { return m_path; }
    QTableWidget *grid() const { return m_grid; }
    QString errorText() const; // what the last load or save refused, empty when none
    // Reads the file into the grid; false (with the error shown) when it cannot be read.
    bool reload();
    void addTool();            // a new row with the next free tool number
    void removeSelectedTool(); // the current row
    // The grid as a table; false with *error (translated, naming the row) when a row is bad.
    bool tableFromGrid(gcode::ToolTable *table, QString *error) const;
    bool save(); // checks, writes atomically; saved() on success

signals:
    void saved(const gcode::ToolTable &table);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void setRow(int row, const gcode::ToolEntry &entry);
    void showError(const QString &text);

    QString m_path;
    QTableWidget *m_grid;
    QLabel *m_file;
    QLabel *m_error;
    QPushButton *m_add, *m_remove, *m_save, *m_close;
    std::vector<gcode::ToolEntry> m_rows; // as read, for the words the grid does not show
};

} // namespace frezka::gui
