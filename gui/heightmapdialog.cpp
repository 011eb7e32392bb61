// Machine › Height map: probe, show, save / load, apply. See heightmapdialog.h.

#include "heightmapdialog.h"

#include "heightmapmesh.h"

#include "session/machinelink.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace frezka::gui {

namespace {

QDoubleSpinBox *spin(const char *name, double lo, double hi, double value, int decimals = 3)
{
    auto *s = new QDoubleSpinBox;
    s->setObjectName(QLatin1String(name));
    s->setRange(lo, hi);
    s->setDecimals(decimals);
    s->setValue(value);
    return s;
}

QPushButton *button(const char *name)
{
    auto *b = new QPushButton;
    b->setObjectName(QLatin1String(name));
    return b;
}

} // namespace

HeightMapDialog::HeightMapDialog(session::MachineLink &link, const machine::MachineConfig &config,
                                 QWidget *parent)
    : QDialog(parent)
    , m_link(link)
    , m_config(config)
    , m_probe(std::make_unique<session::HeightProbe>(link, config))
{
    setObjectName(QStringLiteral("heightMapDialog"));
    buildForm();
    connect(
        m_probe.get(), &session::HeightProbe::pointProbed, this,
        [this](int i, int j, double, int done, int total) { onPointProbed(i, j, done, total); });
    connect(m_probe.get(), &session::HeightProbe::finished, this, &HeightMapDialog::onFinished);
    connect(&m_link, &session::MachineLink::stateChanged, this, [this] { updateButtons(); });
    retranslate();
    updateButtons();
}

HeightMapDialog::~HeightMapDialog()
{
    if (m_probe->running())
        m_probe->cancel(); // the machine is not left probing without a dialog to show it
}

// The form, the buttons, the progress and the map's table (texts in retranslate()); one
// function over 60 lines because it is the dialog's whole layout, read top to bottom.
void HeightMapDialog::buildForm()
{
    m_area = {spin("areaX0", -10000, 10000, 0), spin("areaY0", -10000, 10000, 0),
              spin("areaX1", -10000, 10000, 50), spin("areaY1", -10000, 10000, 50)};
    m_spacing = spin("spacing", 0.5, 1000, 10);
    m_clearance = spin("clearance", 0.1, 100, 2);
    m_depth = spin("depth", 0.1, 100, 3);
    m_feed = spin("probeFeed", 1, 5000, 100, 0);
    for (QLabel *&l : m_labels)
        l = new QLabel;
    auto *form = new QGridLayout;
    form->addWidget(m_labels[0], 0, 0);
    form->addWidget(m_area[0], 0, 1);
    form->addWidget(m_area[2], 0, 2);
    form->addWidget(m_labels[1], 1, 0);
    form->addWidget(m_area[1], 1, 1);
    form->addWidget(m_area[3], 1, 2);
    m_fromProgram = button("areaFromProgram");
    form->addWidget(m_fromProgram, 2, 1, 1, 2);
    const std::array<QDoubleSpinBox *, 4> values{m_spacing, m_clearance, m_depth, m_feed};
    for (int k = 0; k < 4; ++k) {
        form->addWidget(m_labels[std::size_t(k + 2)], k + 3, 0);
        form->addWidget(values[std::size_t(k)], k + 3, 1);
    }
    m_probeButton = button("probe");
    m_cancel = button("cancelProbe");
    auto *probeRow = new QHBoxLayout;
    probeRow->addWidget(m_probeButton);
    probeRow->addWidget(m_cancel);
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("probeProgress"));
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("probeStatus"));
    m_status->setWordWrap(true);
    m_error = new QLabel;
    m_error->setObjectName(QStringLiteral("heightMapError"));
    m_error->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("color: #c00;"));
    m_range = new QLabel;
    m_range->setObjectName(QStringLiteral("heightRange"));
    m_table = new QTableWidget;
    m_table->setObjectName(QStringLiteral("heightTable"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_zeroAtReference = new QCheckBox;
    m_zeroAtReference->setObjectName(QStringLiteral("zeroAtReference"));
    m_zeroAtReference->setChecked(true);
    m_save = button("saveMap");
    m_load = button("loadMap");
    m_apply = button("applyMap");
    m_remove = button("removeMap");
    auto *fileRow = new QHBoxLayout;
    for (QPushButton *b : {m_save, m_load, m_apply, m_remove})
        fileRow->addWidget(b);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(probeRow);
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(m_error);
    layout->addWidget(m_range);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_zeroAtReference);
    layout->addLayout(fileRow);
    connectButtons();
}

void HeightMapDialog::connectButtons()
{
    connect(m_fromProgram, &QPushButton::clicked, this, &HeightMapDialog::useProgramArea);
    connect(m_probeButton, &QPushButton::clicked, this, [this] { probe(); });
    connect(m_cancel, &QPushButton::clicked, this, &HeightMapDialog::cancelProbe);
    connect(m_save, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save height map"), QString(),
                                                          tr("Height maps (*.csv)"));
        if (!path.isEmpty())
            saveTo(path);
    });
    connect(m_load, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Load height map"), QString(),
                                                          tr("Height maps (*.csv)"));
        if (!path.isEmpty())
            loadFrom(path);
    });
    connect(m_apply, &QPushButton::clicked, this, [this] {
        if (m_map)
            emit applyRequested(*m_map, zeroAtReference());
    });
    connect(m_remove, &QPushButton::clicked, this, &HeightMapDialog::removeRequested);
}

void HeightMapDialog::retranslate()
{
    setWindowTitle(tr("Height map"));
    m_labels[0]->setText(tr("Area X from / to (mm)"));
    m_labels[1]->setText(tr("Area Y from / to (mm)"));
    m_labels[2]->setText(tr("Spacing (mm)"));
    m_labels[3]->setText(tr("Clearance above Z 0 (mm)"));
    m_labels[4]->setText(tr("Probe depth below Z 0 (mm)"));
    m_labels[5]->setText(tr("Probe feed (mm/min)"));
    m_fromProgram->setText(tr("Area of the loaded program"));
    m_probeButton->setText(tr("Probe"));
    m_cancel->setText(tr("Cancel"));
    m_save->setText(tr("Save…"));
    m_load->setText(tr("Load…"));
    m_apply->setText(tr("Apply to the program"));
    m_remove->setText(tr("Remove from the program"));
    m_zeroAtReference->setText(
        tr("On Apply, set the work's Z zero on the surface at the first point"));
    m_probeButton->setToolTip(tr("Probes the grid with G38.2 at every point (the probe input "
                                 "IN15), back up to the clearance between the points."));
    showMap();
}

void HeightMapDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void HeightMapDialog::setWorkZero(const session::Axes4 &workZeroMm)
{
    m_workZero = workZeroMm;
}

void HeightMapDialog::setProgramArea(std::optional<std::array<double, 4>> machineArea)
{
    m_programArea = machineArea;
    updateButtons();
}

void HeightMapDialog::setApplied(bool applied)
{
    m_applied = applied;
    updateButtons();
}

void HeightMapDialog::useProgramArea()
{
    if (!m_programArea)
        return;
    for (std::size_t k = 0; k < 4; ++k)
        m_area[k]->setValue((*m_programArea)[k] - m_workZero[k % 2]);
}

session::HeightProbeSettings HeightMapDialog::settings() const
{
    session::HeightProbeSettings s;
    s.x0Mm = std::min(m_area[0]->value(), m_area[2]->value()) + m_workZero[0];
    s.x1Mm = std::max(m_area[0]->value(), m_area[2]->value()) + m_workZero[0];
    s.y0Mm = std::min(m_area[1]->value(), m_area[3]->value()) + m_workZero[1];
    s.y1Mm = std::max(m_area[1]->value(), m_area[3]->value()) + m_workZero[1];
    s.spacingMm = m_spacing->value();
    s.clearanceZMm = m_workZero[2] + m_clearance->value();
    s.bottomZMm = m_workZero[2] - m_depth->value();
    s.feedMmPerMin = m_feed->value();
    return s;
}

bool HeightMapDialog::probe()
{
    m_error->clear();
    if (!m_probe->start(settings())) {
        showError(m_probe->error());
        return false;
    }
    m_map = m_probe->map();
    m_progress->setRange(0, m_probe->pointsTotal());
    m_progress->setValue(0);
    m_status->setText(tr("Probing %1 points…").arg(m_probe->pointsTotal()));
    showMap();
    updateButtons();
    emit mapChanged();
    return true;
}

void HeightMapDialog::cancelProbe()
{
    m_probe->cancel();
    updateButtons();
}

bool HeightMapDialog::isProbing() const
{
    return m_probe->running();
}

void HeightMapDialog::onPointProbed(int, int, int done, int total)
{
    m_map = m_probe->map();
    m_progress->setValue(done);
    m_status->setText(tr("Probed %1 of %2 points.").arg(done).arg(total));
    showMap();
    emit mapChanged();
}

void HeightMapDialog::onFinished(bool ok)
{
    m_map = m_probe->map();
    if (ok) {
        m_status->setText(tr("All %1 points probed.").arg(m_probe->pointsTotal()));
    } else {
        m_map.reset(); // an incomplete map must not bend a program
        m_status->setText(tr("Probing stopped after %1 of %2 points.")
                              .arg(m_probe->pointsDone())
                              .arg(m_probe->pointsTotal()));
        showError(m_probe->error());
    }
    showMap();
    updateButtons();
    emit mapChanged();
    emit probingFinished(ok);
}

void HeightMapDialog::setMap(const gcode::HeightMap &map)
{
    m_map = map;
    showMap();
    updateButtons();
    emit mapChanged();
}

std::vector<bool> HeightMapDialog::probedNodes() const
{
    if (!m_map)
        return {};
    std::vector<bool> probed(std::size_t(m_map->countX()) * std::size_t(m_map->countY()),
                             !m_probe->running());
    if (m_probe->running()) {
        const auto order = session::serpentineOrder(m_map->countX(), m_map->countY());
        for (int k = 0; k < m_probe->pointsDone() && k < int(order.size()); ++k) {
            const auto [i, j] = order[std::size_t(k)];
            probed[std::size_t(j) * std::size_t(m_map->countX()) + std::size_t(i)] = true;
        }
    }
    return probed;
}

bool HeightMapDialog::saveTo(const QString &path)
{
    QString error;
    if (!m_map || !m_map->save(path, &error)) {
        showError(error.isEmpty() ? tr("There is no height map to save: probe or load one.")
                                  : error);
        return false;
    }
    m_status->setText(tr("Height map saved to %1.").arg(path));
    return true;
}

bool HeightMapDialog::loadFrom(const QString &path)
{
    QString error;
    std::optional<gcode::HeightMap> map = gcode::HeightMap::load(path, &error);
    if (!map) {
        showError(error);
        return false;
    }
    m_error->clear();
    setMap(*map);
    m_status->setText(tr("Height map loaded from %1.").arg(path));
    return true;
}

QString HeightMapDialog::statusText() const
{
    return m_status->text();
}

QString HeightMapDialog::errorText() const
{
    return m_error->text();
}

bool HeightMapDialog::zeroAtReference() const
{
    return m_zeroAtReference->isChecked();
}

void HeightMapDialog::showError(const QString &text)
{
    m_error->setText(text);
}

// The colour map: a row per Y (the highest Y on top, as seen from above), a column per X, each
// cell the height (mm) on its colour; nodes not probed yet are empty.
void HeightMapDialog::showMap()
{
    if (!m_map) {
        m_table->clear();
        m_table->setRowCount(0);
        m_table->setColumnCount(0);
        m_range->clear();
        return;
    }
    const gcode::HeightMap &map = *m_map;
    const int done = m_probe->running() ? m_probe->pointsDone() : map.countX() * map.countY();
    const auto order = session::serpentineOrder(map.countX(), map.countY());
    m_table->setRowCount(map.countY());
    m_table->setColumnCount(map.countX());
    for (int i = 0; i < map.countX(); ++i)
        m_table->setHorizontalHeaderItem(
            i, new QTableWidgetItem(QString::number(map.nodeX(i) - m_workZero[0], 'f', 1)));
    for (int j = 0; j < map.countY(); ++j)
        m_table->setVerticalHeaderItem(
            map.countY() - 1 - j,
            new QTableWidgetItem(QString::number(map.nodeY(j) - m_workZero[1], 'f', 1)));
    const double lo = map.minZ(), hi = map.maxZ();
    m_table->clearContents();
    for (int k = 0; k < int(order.size()); ++k) {
        const auto [i, j] = order[std::size_t(k)];
        if (k >= done)
            continue;
        auto *item = new QTableWidgetItem(QString::number(map.z(i, j), 'f', 3));
        item->setBackground(heightMapColour(hi > lo ? (map.z(i, j) - lo) / (hi - lo) : 0.5));
        item->setTextAlignment(Qt::AlignCenter);
        m_table->setItem(map.countY() - 1 - j, i, item);
    }
    m_range->setText(tr("%1 x %2 points, heights %3 to %4 mm from the first point (machine Z "
                        "%5)")
                         .arg(map.countX())
                         .arg(map.countY())
                         .arg(lo, 0, 'f', 3)
                         .arg(hi, 0, 'f', 3)
                         .arg(map.probing().referenceZMm, 0, 'f', 3));
}

void HeightMapDialog::updateButtons()
{
    const bool probing = m_probe->running();
    const bool idle = m_link.state().mode == driver::MachineMode::Idle;
    m_probeButton->setEnabled(!probing && idle);
    m_cancel->setEnabled(probing);
    m_fromProgram->setEnabled(m_programArea.has_value() && !probing);
    m_save->setEnabled(m_map.has_value() && !probing);
    m_load->setEnabled(!probing);
    m_apply->setEnabled(m_map.has_value() && !probing);
    m_remove->setEnabled(m_applied);
}

} // namespace frezka::gui
