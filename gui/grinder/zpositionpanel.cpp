#include "gui/grinder/zpositionpanel.h"

#include <QDoubleSpinBox>
#include <QFont>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTime>
#include <QVBoxLayout>

#include <cmath>

namespace frezka::gui {

using namespace frezka::grinder;

ZPositionPanel::ZPositionPanel(QWidget *parent)
    : QWidget(parent)
    , m_form(new QLabel(this))
    , m_position(new QLabel(QStringLiteral("—"), this))
    , m_readButton(new QPushButton(tr("Read position (Z?)"), this))
    , m_target(new QDoubleSpinBox(this))
    , m_goButton(new QPushButton(tr("GO"), this))
    , m_status(new QLabel(this))
    , m_log(new QPlainTextEdit(this))
{
    m_position->setObjectName(QStringLiteral("zPosition"));
    m_readButton->setObjectName(QStringLiteral("readButton"));
    m_goButton->setObjectName(QStringLiteral("goButton"));
    m_target->setObjectName(QStringLiteral("goTarget"));
    QFont big = m_position->font();
    big.setPointSize(big.pointSize() * 2);
    big.setBold(true);
    m_position->setFont(big);
    m_target->setRange(-kMaxGoUm / 1000.0, kMaxGoUm / 1000.0);
    m_target->setDecimals(3);
    m_target->setSuffix(tr(" mm"));
    m_goButton->setToolTip(tr("Move the table to this Z position (selector in PGN)."));
    m_status->setWordWrap(true);
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(1000);

    auto *goRow = new QHBoxLayout;
    goRow->addWidget(m_target, 1);
    goRow->addWidget(m_goButton);
    auto *form = new QFormLayout;
    form->addRow(tr("Protocol:"), m_form);
    form->addRow(tr("Z position:"), m_position);
    form->addRow(QString(), m_readButton);
    form->addRow(tr("Go to:"), goRow);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_status);
    layout->addWidget(m_log, 1);

    connect(m_readButton, &QPushButton::clicked, this, &ZPositionPanel::readPosition);
    connect(m_goButton, &QPushButton::clicked, this, [this] { goTo(m_target->value()); });
    setSession(nullptr);
}

void ZPositionPanel::setSession(ZLinkSession *session)
{
    if (m_session)
        disconnect(m_session, nullptr, this, nullptr);
    m_session = session;
    m_frames = m_skipped = 0;
    if (!m_session) {
        m_form->setText(tr("not connected in a Z-position mode"));
    } else {
        m_form->setText(m_session->form() == 1
                            ? tr("FORM=1: ASCII both ways (Z?, GO)")
                            : tr("FORM=2: binary frames sent by the controller"));
        connect(m_session, &ZLinkSession::positionReceived, this, &ZPositionPanel::onPosition);
        connect(m_session, &ZLinkSession::replyFailed, this, [this](const QString &message) {
            m_status->setText(message);
            updateEnabled();
        });
        connect(m_session, &ZLinkSession::bytesSkipped, this, [this](int count) {
            m_skipped += count;
            m_status->setText(tr("%1 bytes skipped to find the frame start.").arg(m_skipped));
        });
        connect(m_session, &ZLinkSession::traced, this, [this](const QString &line) {
            m_log->appendPlainText(QTime::currentTime().toString(QStringLiteral("HH:mm:ss.zzz  ")) +
                                   line);
        });
    }
    updateEnabled();
}

void ZPositionPanel::updateEnabled()
{
    const bool ask = m_session && m_session->form() == 1 && !m_session->isWaiting();
    m_readButton->setEnabled(ask);
    m_goButton->setEnabled(ask);
    m_target->setEnabled(m_session && m_session->form() == 1);
}

bool ZPositionPanel::readPosition()
{
    if (!m_session || !m_session->query())
        return false;
    m_status->setText(tr("Asking for the position…"));
    updateEnabled();
    return true;
}

bool ZPositionPanel::goTo(double targetMm)
{
    const auto targetUm = static_cast<std::int64_t>(std::llround(targetMm * 1000.0));
    if (!m_session || !m_session->go(targetUm))
        return false;
    m_status->setText(
        tr("Moving to %1 mm…").arg(QString::fromStdString(formatMillimetres(targetUm))));
    updateEnabled();
    return true;
}

void ZPositionPanel::onPosition(qint64 positionUm)
{
    ++m_frames;
    m_position->setText(tr("%1 mm").arg(QString::fromStdString(formatMillimetres(positionUm))));
    if (m_session && m_session->form() == 2)
        m_status->setText(tr("%1 frames received.").arg(m_frames));
    else
        m_status->setText(tr("Position received at %1.")
                              .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss"))));
    updateEnabled();
}

QString ZPositionPanel::positionText() const
{
    return m_position->text();
}

QString ZPositionPanel::statusText() const
{
    return m_status->text();
}

} // namespace frezka::gui
