#include "commissiondialog.h"

#include "driver/link/emulatorport.h"
#include "driver/link/emulatortransport.h"
#include "driver/link/serialtransport.h"
#include "driver/link/tracerecorder.h"
#include "driver/link/tracingtransport.h"
#include "session/commissionreport.h"
#include "session/unitprobe.h"

#include <QDir>
#include <QEventLoop>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

namespace frezka::gui {

namespace {

bool isEmulator(const machine::MachineConfig &profile)
{
    return profile.link.port.empty() || profile.link.port == "emulator";
}

QPushButton *makeButton(const QString &text, const char *name, QWidget *parent)
{
    auto *b = new QPushButton(text, parent);
    b->setObjectName(QLatin1String(name));
    b->setEnabled(false);
    return b;
}

std::vector<std::pair<std::string, std::string>> header(const machine::MachineConfig &profile)
{
    return {{"variant", std::string(protocol::variantInfo(profile.unit.variant).id)},
            {"baud", std::to_string(profile.link.baud)},
            {"operation", "commission"}};
}

} // namespace

CommissionDialog::CommissionDialog(const machine::MachineConfig &profile,
                                   const QString &profilePath, QWidget *parent)
    : QDialog(parent)
    , m_result(session::startCommission(profile, profile.link.port))
    , m_profilePath(profilePath)
    , m_recorder(std::make_unique<driver::TraceRecorder>())
{
    setWindowTitle(tr("Commission this machine"));
    setObjectName(QStringLiteral("commissionDialog"));
    m_steps = new QListWidget(this);
    m_steps->setObjectName(QStringLiteral("commissionSteps"));
    m_prompt = new QLabel(tr("Start runs the steps that move nothing at once; each step that "
                             "moves or switches something waits for Run or Skip."),
                          this);
    m_prompt->setWordWrap(true);
    m_number = new QLineEdit(this);
    m_number->setObjectName(QStringLiteral("commissionNumber"));
    m_number->setPlaceholderText(tr("measured mm (empty: as asked)"));
    m_number->setEnabled(false);
    m_start = makeButton(tr("&Start"), "commissionStart", this);
    m_start->setEnabled(true);
    m_run = makeButton(tr("&Run step"), "commissionRun", this);
    m_skip = makeButton(tr("S&kip step"), "commissionSkip", this);
    m_yes = makeButton(tr("&Yes"), "commissionYes", this);
    m_no = makeButton(tr("&No"), "commissionNo", this);
    m_ok = makeButton(tr("&OK"), "commissionOk", this);
    m_saveReport = makeButton(tr("Save &report…"), "commissionSaveReport", this);
    m_saveProfile = makeButton(tr("Save &profile…"), "commissionSaveProfile", this);
    auto *close = new QPushButton(tr("&Close"), this);
    auto *answers = new QHBoxLayout;
    for (QWidget *w : {static_cast<QWidget *>(m_start), static_cast<QWidget *>(m_run),
                       static_cast<QWidget *>(m_skip), static_cast<QWidget *>(m_yes),
                       static_cast<QWidget *>(m_no), static_cast<QWidget *>(m_number),
                       static_cast<QWidget *>(m_ok)})
        answers->addWidget(w);
    auto *files = new QHBoxLayout;
    files->addWidget(m_saveReport);
    files->addWidget(m_saveProfile);
    files->addStretch();
    files->addWidget(close);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_steps);
    layout->addWidget(m_prompt);
    layout->addLayout(answers);
    layout->addLayout(files);
    connect(close, &QPushButton::clicked, this, &CommissionDialog::reject);
    connectButtons();
    if (isEmulator(profile)) {
        m_emulator = new driver::EmulatorTransport(driver::unitOptionsFor(profile), {});
        m_transport =
            std::make_unique<driver::TracingTransport>(m_emulator, *m_recorder, header(profile));
    }
    showSteps();
    resize(640, 520);
}

CommissionDialog::~CommissionDialog() = default;

void CommissionDialog::connectButtons()
{
    connect(m_start, &QPushButton::clicked, this, &CommissionDialog::start);
    connect(m_run, &QPushButton::clicked, this, [this] { answer(Answer::Run); });
    connect(m_skip, &QPushButton::clicked, this, [this] { answer(Answer::Skip); });
    connect(m_yes, &QPushButton::clicked, this, [this] { answer(Answer::Yes); });
    connect(m_no, &QPushButton::clicked, this, [this] { answer(Answer::No); });
    connect(m_ok, &QPushButton::clicked, this, [this] { answer(Answer::Number); });
    connect(m_saveReport, &QPushButton::clicked, this, &CommissionDialog::saveReportAs);
    connect(m_saveProfile, &QPushButton::clicked, this, &CommissionDialog::saveProfileAs);
}

emulator::Unit *CommissionDialog::emulatedUnit()
{
    return m_emulator ? &m_emulator->unit() : nullptr;
}

void CommissionDialog::showSteps()
{
    m_steps->clear();
    for (const auto &s : m_result.steps) {
        QString line = QStringLiteral("[%1] %2").arg(session::stepResultText(s.result), s.title);
        if (!s.details.isEmpty())
            line += QStringLiteral("\n    ") + s.details;
        m_steps->addItem(line);
    }
}

void CommissionDialog::start()
{
    if (m_running)
        return;
    m_running = true;
    m_start->setEnabled(false);
    const machine::MachineConfig &profile = m_result.profileBefore;
    const int baud = profile.link.baud;
    const QString port = QString::fromStdString(profile.link.port);
    m_prompt->setText(tr("Checking the unit (nothing moves)…"));
    std::unique_ptr<driver::Transport> serial;
    if (!m_transport)
        serial = std::make_unique<driver::TracingTransport>(new driver::SerialTransport(port, baud),
                                                            *m_recorder, header(profile));
    QString error;
    const bool opened = session::runUnitProbe(m_transport ? *m_transport : *serial, profile, baud,
                                              m_result, &error);
    m_probeTrace = emulator::formatTrace(m_recorder->snapshot());
    showSteps();
    if (!opened) {
        session::skipOperatorSteps(m_result, tr("the port could not be opened: %1").arg(error));
    } else {
        session::MoveOptions options;
        options.factory = [this, &profile](const driver::ConnectionSettings &s,
                                           const machine::MachineConfig &, QObject *parent,
                                           QString *) -> driver::Transport * {
            if (m_transport)
                return m_transport.get();
            return new driver::TracingTransport(new driver::SerialTransport(s.portName, s.baud),
                                                *m_recorder, header(profile), parent);
        };
        session::runOperatorSteps(port, baud, m_result, *this, options);
    }
    m_result.trace = m_probeTrace + emulator::formatTrace(m_recorder->snapshot());
    showSteps();
    m_prompt->setText(tr("Done. Save the report (and the updated profile, under a new name)."));
    for (QWidget *w : {static_cast<QWidget *>(m_run), static_cast<QWidget *>(m_skip),
                       static_cast<QWidget *>(m_yes), static_cast<QWidget *>(m_no),
                       static_cast<QWidget *>(m_number), static_cast<QWidget *>(m_ok)})
        w->setEnabled(false);
    m_saveReport->setEnabled(true);
    m_saveProfile->setEnabled(true);
    m_running = false;
    emit stepsFinished();
}

CommissionDialog::Answer CommissionDialog::waitFor(const QString &prompt,
                                                   std::initializer_list<QWidget *> enabled)
{
    if (m_cancelled)
        return Answer::Skip;
    showSteps();
    m_prompt->setText(prompt);
    for (QWidget *w : enabled)
        w->setEnabled(true);
    m_answer = Answer::None;
    emit operatorAsked();
    if (m_answer == Answer::None) {
        QEventLoop loop;
        m_wait = &loop;
        loop.exec();
        m_wait = nullptr;
    }
    for (QWidget *w : enabled)
        w->setEnabled(false);
    return m_answer;
}

void CommissionDialog::answer(Answer a)
{
    m_answer = a;
    if (m_wait)
        m_wait->quit();
}

bool CommissionDialog::confirm(const session::CommissionStep &step)
{
    return waitFor(QStringLiteral("<b>%1</b><br>%2").arg(step.title, step.does), {m_run, m_skip}) ==
           Answer::Run;
}

bool CommissionDialog::ask(const QString &question)
{
    return waitFor(question, {m_yes, m_no}) == Answer::Yes;
}

std::optional<double> CommissionDialog::askNumber(const QString &question)
{
    m_number->clear();
    if (waitFor(question, {m_number, m_ok}) != Answer::Number)
        return std::nullopt;
    bool ok = false;
    const double v = QLocale().toDouble(m_number->text().trimmed(), &ok);
    if (ok)
        return v;
    const double c = m_number->text().trimmed().toDouble(&ok);
    return ok ? std::optional<double>(c) : std::nullopt;
}

void CommissionDialog::instruct(const QString &text)
{
    m_prompt->setText(text);
    emit operatorInstructed(text);
}

void CommissionDialog::reject()
{
    if (m_running) { // the steps end first: every later one is skipped
        m_cancelled = true;
        answer(Answer::Skip);
        return;
    }
    QDialog::reject();
}

QString CommissionDialog::reportText() const
{
    return session::commissionReportText(m_result);
}

bool CommissionDialog::saveReport(const QString &path, QString *error) const
{
    return session::saveCommissionText(path, reportText(), error);
}

bool CommissionDialog::saveProfile(const QString &path, QString *error) const
{
    return session::saveCommissionedProfile(m_result.profileAfter, path, m_profilePath, error);
}

void CommissionDialog::saveReportAs()
{
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save the commissioning report"),
        QDir::homePath() + QStringLiteral("/frezka-commission.txt"), tr("Text (*.txt)"));
    QString error;
    if (!path.isEmpty() && !saveReport(path, &error))
        QMessageBox::warning(this, windowTitle(), error);
}

void CommissionDialog::saveProfileAs()
{
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Save the updated profile under a new name"),
                                     QDir::homePath() + QStringLiteral("/frezka-commissioned.json"),
                                     tr("Machine profiles (*.json)"));
    QString error;
    if (!path.isEmpty() && !saveProfile(path, &error))
        QMessageBox::warning(this, windowTitle(), error);
}

} // namespace frezka::gui
