#pragma once
// HEDIT's editor: the 0x2E bytes of hard-chrome data (controller addresses 0x1100..0x112D,
// values for parametric plunge and traverse grinding). The manual gives the block's address
// and length but not its fields (HEDIT's screen, its only description, is lost), so every byte
// is shown raw — address, hex and decimal — edited in place and written back unchanged
// otherwise: a load-edit-save round trip changes only the bytes edited.

#include "driver/grinder/frame.h"

#include <QWidget>

#include <functional>

class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace frezka::gui {

class HardChromeEditor : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kBaseAddress = 0x1100;
    // Returns the chosen path or empty; tests set their own so no modal dialog appears.
    using FileChooser = std::function<QString(bool save, const QString &suggestion)>;

    explicit HardChromeEditor(QWidget *parent = nullptr);
    void setFileChooser(FileChooser chooser) { m_chooser = std::move(chooser); }

    // Takes 46 bytes and their header; false (with the reason shown) for another length.
    bool setData(const QByteArray &data, const grinder::Header &header);
    QByteArray data() const { return m_data; }
    QString headerText() const;
    // Sets the byte at `address` (0x1100..0x112D); false when out of range.
    bool setByte(int address, int value);
    bool openFile(const QString &path);
    // A Frezka grinder file (system hedit, the header) or, for ".bin", the bare 46 bytes.
    bool saveFile(const QString &path);
    QString statusText() const;

signals:
    // "Send to controller": the data and header to load with the HEDIT family.
    void sendRequested(const QByteArray &data, const QString &header);
    // "Take the received data": the window answers with setData().
    void receivedDataWanted();

private:
    void fillTable();
    void onCellChanged(int row, int column);
    QString choose(bool save, const QString &suggestion);

    QByteArray m_data;
    FileChooser m_chooser;
    bool m_filling = false;
    QTableWidget *m_table;
    QLineEdit *m_header;
    QLabel *m_status;
};

} // namespace frezka::gui
