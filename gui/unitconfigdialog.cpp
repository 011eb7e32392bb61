#include "unitconfigdialog.h"

#include "eepromdecode.h"

#include "driver/link/drivererror.h"
#include "driver/link/machinecontroller.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace frezka::gui {

UnitConfigDialog::UnitConfigDialog(driver::MachineController *controller,
                                   const machine::MachineConfig &profile, QWidget *parent)
    : QDialog(parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("unitConfigDialog"));
    m_table = new QTableWidget(this);
    m_table->setColumnCount(5);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setSectionResizeMode(4, QHeaderView::Stretch);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    m_read = new QPushButton(this);
    m_writeDiff = new QPushButton(this);
    m_writeAll = new QPushButton(this);
    m_close = new QPushButton(this);
    m_read->setObjectName(QStringLiteral("eepromRead"));
    m_writeDiff->setObjectName(QStringLiteral("eepromWriteDifferences"));
    m_writeAll->setObjectName(QStringLiteral("eepromWriteAll"));
    connect(m_read, &QPushButton::clicked, this, &UnitConfigDialog::readUnit);
    connect(m_writeDiff, &QPushButton::clicked, this, [this] { requestWrite(false); });
    connect(m_writeAll, &QPushButton::clicked, this, [this] { requestWrite(true); });
    connect(m_close, &QPushButton::clicked, this, &QDialog::close);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_read);
    buttons->addWidget(m_writeDiff);
    buttons->addWidget(m_writeAll);
    buttons->addStretch();
    buttons->addWidget(m_close);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_status);
    layout->addLayout(buttons);
    resize(860, 560);

    m_timeout.setSingleShot(true);
    m_timeout.setInterval(5000);
    connect(&m_timeout, &QTimer::timeout, this, [this] {
        if (m_current)
            fail(tr("No reply to %1 within 5 s.").arg(m_current->command));
    });
    connect(m_controller, &driver::MachineController::logLine, this, &UnitConfigDialog::onLogLine);
    connect(m_controller, &driver::MachineController::errorOccurred, this,
            &UnitConfigDialog::onError);
    setProfile(profile);
    retranslate();
}

void UnitConfigDialog::setProfile(const machine::MachineConfig &profile)
{
    m_profile = profile;
    m_rows.clear();
    for (const auto &e : machine::eepromEntries(profile))
        m_rows.push_back({e, std::nullopt, false});
    refreshTable();
}

int UnitConfigDialog::differences() const
{
    int n = 0;
    for (const auto &r : m_rows)
        n += r.unit && !eepromSame(r.wanted.kind, *r.unit, r.wanted.value);
    return n;
}

void UnitConfigDialog::readUnit()
{
    if (isBusy())
        return;
    m_failed = false;
    for (std::size_t i = 0; i < m_rows.size(); ++i)
        m_queue.push_back({eepromReadCommand(m_rows[i].wanted), int(i), false, false});
    m_status->setText(tr("Reading the unit's EEPROM…"));
    next();
}

void UnitConfigDialog::requestWrite(bool all)
{
    if (isBusy())
        return;
    const int n = all ? int(m_rows.size()) : differences();
    if (!all && n == 0) {
        writeUnit(false); // nothing to write: says so
        return;
    }
    auto *box = new QMessageBox(
        QMessageBox::Question, tr("Write the unit's EEPROM"),
        all ? tr("Write all %n value(s) of the profile into the unit's EEPROM?", nullptr, n)
            : tr("Write the %n value(s) that differ into the unit's EEPROM?", nullptr, n),
        QMessageBox::Yes | QMessageBox::Cancel, this);
    box->setObjectName(QStringLiteral("confirmEepromWrite"));
    box->setInformativeText(tr("The unit keeps them after it is switched off, and the machine "
                               "moves by them from now on."));
    box->setDefaultButton(QMessageBox::Cancel);
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::finished, this, [this, all](int result) {
        if (result == QMessageBox::Yes)
            writeUnit(all);
    });
    box->open();
}

void UnitConfigDialog::writeUnit(bool all)
{
    if (isBusy())
        return;
    m_failed = false;
    for (std::size_t i = 0; i < m_rows.size(); ++i) {
        Row &r = m_rows[i];
        if (!all && r.unit && eepromSame(r.wanted.kind, *r.unit, r.wanted.value))
            continue;
        if (!all && !r.unit)
            continue; // not read yet: read first
        r.verified = false;
        m_queue.push_back({eepromWriteCommand(r.wanted), int(i), true, false});
        m_queue.push_back({eepromReadCommand(r.wanted), int(i), false, true});
    }
    if (m_queue.empty()) {
        m_status->setText(differences() == 0 && !m_rows.empty() && m_rows.front().unit
                              ? tr("The unit already matches the profile.")
                              : tr("Read the unit first."));
        emit finished(true);
        return;
    }
    m_status->setText(
        tr("Writing %n setting(s) and reading them back…", nullptr, int(m_queue.size() / 2)));
    next();
}

void UnitConfigDialog::next()
{
    if (m_queue.empty()) {
        m_current.reset();
        refreshTable();
        if (!m_failed) {
            m_status->setText(statusText());
            emit finished(true);
        }
        return;
    }
    m_current = m_queue.front();
    m_queue.pop_front();
    m_timeout.start();
    m_controller->sendRaw(QStringLiteral("!0") + m_current->command);
}

void UnitConfigDialog::onLogLine(const QString &line)
{
    static const QLatin1String kReply("reply: ");
    if (!m_current || !line.startsWith(kReply))
        return;
    m_timeout.stop();
    const QStringList fields = line.mid(kReply.size()).trimmed().split(QLatin1Char(','));
    bool ok = false;
    const int code = fields.value(0).toInt(&ok, 16) & 0x7;
    if (!ok || code != 0) {
        fail(
            tr("The unit refused %1 (reply %2).").arg(m_current->command, line.mid(kReply.size())));
        return;
    }
    Row &row = m_rows[std::size_t(m_current->row)];
    if (!m_current->write) {
        const QString v = fields.value(1);
        const double value = row.wanted.kind == machine::EepromKind::Byte
                                 ? double(v.toUInt(&ok, 16))
                                 : v.toDouble(&ok);
        if (!ok) {
            fail(tr("Cannot read the value in the reply to %1: %2")
                     .arg(m_current->command, line.mid(kReply.size())));
            return;
        }
        row.unit = value;
        if (m_current->verify) {
            row.verified = eepromSame(row.wanted.kind, value, row.wanted.value);
            if (!row.verified) {
                fail(tr("Read-back of %1 gives %2, not the %3 written.")
                         .arg(eepromLabel(m_profile.unit.variant, row.wanted.address),
                              eepromValueText(row.wanted.kind, value),
                              eepromValueText(row.wanted.kind, row.wanted.value)));
                return;
            }
        }
    }
    next();
}

void UnitConfigDialog::onError(const driver::MachineError &error)
{
    if (m_current)
        fail(tr("%1 failed: %2")
                 .arg(m_current->command, driver::translatedText(error.reason, true)));
}

void UnitConfigDialog::fail(const QString &why)
{
    m_timeout.stop();
    m_queue.clear();
    m_current.reset();
    m_failed = true;
    refreshTable();
    m_status->setText(why);
    m_status->setStyleSheet(QStringLiteral("color: #c00; font-weight: bold;"));
    emit finished(false);
}

QString UnitConfigDialog::statusText() const
{
    int read = 0;
    for (const auto &r : m_rows)
        read += r.unit.has_value();
    if (read == 0)
        return tr("Not read yet.");
    const int diff = differences();
    return diff == 0 ? tr("The unit matches the profile (%n setting(s) compared).", nullptr, read)
                     : tr("%n setting(s) differ from the profile.", nullptr, diff);
}

void UnitConfigDialog::refreshTable()
{
    m_status->setStyleSheet(QString());
    m_table->setRowCount(int(m_rows.size()));
    const auto variant = m_profile.unit.variant;
    for (int i = 0; i < int(m_rows.size()); ++i) {
        const Row &r = m_rows[std::size_t(i)];
        const bool same = r.unit && eepromSame(r.wanted.kind, *r.unit, r.wanted.value);
        const QString unitText =
            r.unit ? eepromValueText(r.wanted.kind, *r.unit) : QStringLiteral("—");
        const QString meaning = r.unit ? eepromMeaning(variant, r.wanted.address, *r.unit)
                                       : eepromMeaning(variant, r.wanted.address, r.wanted.value);
        const QStringList cells{
            QStringLiteral("0x%1").arg(r.wanted.address, 2, 16, QLatin1Char('0')).toUpper(),
            eepromLabel(variant, r.wanted.address), eepromValueText(r.wanted.kind, r.wanted.value),
            unitText, meaning};
        for (int c = 0; c < cells.size(); ++c) {
            auto *item = new QTableWidgetItem(cells[c]);
            if (r.unit && !same)
                item->setBackground(QColor(255, 190, 190));
            else if (r.verified)
                item->setBackground(QColor(190, 255, 190));
            m_table->setItem(i, c, item);
        }
    }
    m_table->resizeColumnsToContents();
}

void UnitConfigDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void UnitConfigDialog::retranslate()
{
    setWindowTitle(tr("Unit configuration (EEPROM)"));
    m_table->setHorizontalHeaderLabels(
        {tr("Address"), tr("Setting"), tr("Profile"), tr("Unit"), tr("Meaning (unit value)")});
    m_read->setText(tr("Read from unit"));
    m_writeDiff->setText(tr("Write differences"));
    m_writeAll->setText(tr("Write all"));
    m_close->setText(tr("Close"));
    refreshTable();
    m_status->setText(statusText());
}

} // namespace frezka::gui
