#include "gui/grinder/hardchromeeditor.h"

#include "driver/grinder/controllerheader.h"
#include "driver/grinder/grinderfile.h"
#include "driver/grinder/imagecheck.h"
#include "driver/grinder/transfersession.h"

#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSaveFile>
#include <QTableWidget>
#include <QVBoxLayout>

namespace frezka::gui {

using namespace frezka::grinder;

HardChromeEditor::HardChromeEditor(QWidget *parent)
    : QWidget(parent)
    , m_data(int(kHardChromeSize), '\0')
    , m_table(new QTableWidget(int(kHardChromeSize), 3, this))
    , m_header(new QLineEdit(this))
    , m_status(new QLabel(this))
{
    m_table->setObjectName(QStringLiteral("hardChromeTable"));
    m_status->setObjectName(QStringLiteral("hardChromeStatus"));
    m_status->setWordWrap(true);
    m_header->setMaxLength(int(kHeaderSize));
    m_table->setHorizontalHeaderLabels({tr("Address"), tr("Hex"), tr("Decimal")});
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setStretchLastSection(true);
    auto *note = new QLabel(tr("Hard-chrome data for parametric plunge and traverse grinding: "
                               "0x2E bytes from address 0x1100. The manual does not describe "
                               "the single values, so each byte is shown as it is; what you "
                               "do not edit is kept unchanged."),
                            this);
    note->setWordWrap(true);
    auto *open = new QPushButton(tr("Open…"), this);
    auto *save = new QPushButton(tr("Save…"), this);
    auto *take = new QPushButton(tr("Take received data"), this);
    auto *send = new QPushButton(tr("Send to controller"), this);
    send->setObjectName(QStringLiteral("hardChromeSend"));
    auto *buttons = new QHBoxLayout;
    for (QPushButton *button : {open, save, take, send})
        buttons->addWidget(button);
    buttons->addStretch(1);
    auto *headerRow = new QHBoxLayout;
    headerRow->addWidget(new QLabel(tr("Header:"), this));
    headerRow->addWidget(m_header, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(note);
    layout->addLayout(buttons);
    layout->addLayout(headerRow);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_status);

    connect(m_table, &QTableWidget::cellChanged, this, &HardChromeEditor::onCellChanged);
    connect(open, &QPushButton::clicked, this, [this] {
        const QString path = choose(false, QString());
        if (!path.isEmpty())
            openFile(path);
    });
    connect(save, &QPushButton::clicked, this, [this] {
        const QString path = choose(true, QStringLiteral("hedit.frg"));
        if (!path.isEmpty())
            saveFile(path);
    });
    connect(take, &QPushButton::clicked, this, &HardChromeEditor::receivedDataWanted);
    connect(send, &QPushButton::clicked, this,
            [this] { emit sendRequested(m_data, m_header->text()); });
    fillTable();
}

QString HardChromeEditor::choose(bool save, const QString &suggestion)
{
    if (m_chooser)
        return m_chooser(save, suggestion);
    const QString filter = tr("Frezka grinder file (*.frg);;Bare data (*.bin)");
    return save ? QFileDialog::getSaveFileName(this, tr("Save HEDIT data"), suggestion, filter)
                : QFileDialog::getOpenFileName(this, tr("Open HEDIT data"), suggestion,
                                               tr("Grinder files (*.frg *.bin);;All files (*)"));
}

void HardChromeEditor::fillTable()
{
    m_filling = true;
    for (int i = 0; i < m_data.size(); ++i) {
        const auto value = quint8(m_data[i]);
        auto *address = new QTableWidgetItem(
            QStringLiteral("0x%1").arg(kBaseAddress + i, 4, 16, QLatin1Char('0')).toUpper());
        address->setFlags(address->flags() & ~Qt::ItemIsEditable);
        auto *decimal = new QTableWidgetItem(QString::number(value));
        decimal->setFlags(decimal->flags() & ~Qt::ItemIsEditable);
        m_table->setItem(i, 0, address);
        m_table->setItem(i, 1,
                         new QTableWidgetItem(
                             QStringLiteral("%1").arg(value, 2, 16, QLatin1Char('0')).toUpper()));
        m_table->setItem(i, 2, decimal);
    }
    m_filling = false;
}

void HardChromeEditor::onCellChanged(int row, int column)
{
    if (m_filling || column != 1)
        return;
    bool ok = false;
    const int value = m_table->item(row, 1)->text().trimmed().toInt(&ok, 16);
    if (!ok || value < 0 || value > 0xFF) {
        m_status->setText(tr("0x%1: \"%2\" is not a byte in hex (00 to FF); the value is kept.")
                              .arg(kBaseAddress + row, 4, 16, QLatin1Char('0'))
                              .arg(m_table->item(row, 1)->text()));
        fillTable();
        return;
    }
    setByte(kBaseAddress + row, value);
}

bool HardChromeEditor::setByte(int address, int value)
{
    const int offset = address - kBaseAddress;
    if (offset < 0 || offset >= m_data.size() || value < 0 || value > 0xFF)
        return false;
    m_data[offset] = char(value);
    fillTable();
    m_status->setText(tr("0x%1 set to %2.")
                          .arg(address, 4, 16, QLatin1Char('0'))
                          .arg(QStringLiteral("%1").arg(value, 2, 16, QLatin1Char('0')).toUpper()));
    return true;
}

bool HardChromeEditor::setData(const QByteArray &data, const Header &header)
{
    if (std::size_t(data.size()) != kHardChromeSize) {
        m_status->setText(tr("HEDIT data have 46 bytes (0x2E); these have %1. Nothing changed.")
                              .arg(data.size()));
        return false;
    }
    m_data = data;
    m_header->setText(QString::fromLatin1(grinder::headerText(header)));
    fillTable();
    m_status->setText(tr("46 bytes loaded."));
    return true;
}

QString HardChromeEditor::headerText() const
{
    return m_header->text();
}

QString HardChromeEditor::statusText() const
{
    return m_status->text();
}

bool HardChromeEditor::openFile(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        m_status->setText(tr("Cannot read %1: %2").arg(path, file.errorString()));
        return false;
    }
    const QByteArray bytes = file.readAll();
    std::string why;
    const auto decoded = decodeGrinderFile(Bytes(bytes.begin(), bytes.end()), why);
    if (!decoded || (decoded->container && decoded->family != Family::HardChrome)) {
        m_status->setText(
            decoded ? tr("%1 holds %2 data, not HEDIT data.").arg(path, familyName(decoded->family))
                    : tr("%1 is damaged: %2").arg(path, QString::fromStdString(why)));
        return false;
    }
    return setData(QByteArray(reinterpret_cast<const char *>(decoded->data.data()),
                              qsizetype(decoded->data.size())),
                   decoded->container ? decoded->header : Header{});
}

bool HardChromeEditor::saveFile(const QString &path)
{
    QByteArray bytes = m_data;
    if (!path.endsWith(QLatin1String(".bin"), Qt::CaseInsensitive)) {
        const ControllerHeader header = ControllerHeader::fromText(m_header->text());
        if (!header.ok()) {
            m_status->setText(header.error);
            return false;
        }
        GrinderFile file;
        file.family = Family::HardChrome;
        file.header = header.header();
        file.data = Bytes(m_data.begin(), m_data.end());
        const Bytes encoded = encodeGrinderFile(file);
        bytes =
            QByteArray(reinterpret_cast<const char *>(encoded.data()), qsizetype(encoded.size()));
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        m_status->setText(tr("Cannot write %1: %2").arg(path, file.errorString()));
        return false;
    }
    m_status->setText(tr("Saved to %1.").arg(path));
    return true;
}

} // namespace frezka::gui
