#include "LivePanel.h"

#include "PortDiscovery.h"
#include "SignalPlots.h"
#include "TrajectoryView2D.h"
#include "nav/Parameters.h"
#include "nav/Pipeline.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTimer>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace footpath {

namespace {

constexpr double kPlotWindow_s = 10.0;
constexpr int kPlotInterval_ms = 200;      // at most 5 redraws per second
constexpr int kEstimateInterval_ms = 500;

QLabel* valueLabel(QWidget* parent)
{
    auto* label = new QLabel(QStringLiteral("-"), parent);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

}  // namespace

LivePanel::LivePanel(QWidget* parent)
    : QWidget(parent), session_(new DeviceSession(serialDevicePortFactory(), this))
{
    buildUi();
    wireSession();
    refreshPorts();
    updateButtons();
}

LivePanel::~LivePanel()
{
    estimate_.waitForFinished();
}

double LivePanel::latency_s()
{
    const Parameters defaults;
    return defaults.window_half_s + defaults.median_window_s / 2.0;
}

void LivePanel::buildUi()
{
    port_ = new QComboBox(this);
    port_->setEditable(true);
    port_->setObjectName(QStringLiteral("livePort"));
    port_->setToolTip(tr("A serial port, or type a path such as the emulator's pseudo-terminal"));
    port_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    auto* refresh = new QPushButton(tr("Refresh"), this);
    connect(refresh, &QPushButton::clicked, this, &LivePanel::refreshPorts);

    baud_ = new QComboBox(this);
    baud_->setObjectName(QStringLiteral("liveBaud"));
    baud_->addItem(tr("Auto (probe)"), 0);
    for (int baud : {115200, 230400, 460800, 921600})
        baud_->addItem(QString::number(baud), baud);

    rate_ = new QSpinBox(this);
    rate_->setObjectName(QStringLiteral("liveRate"));
    rate_->setRange(1, 2000);
    rate_->setValue(100);
    rate_->setSuffix(tr(" Hz"));

    connect_ = new QPushButton(tr("Connect"), this);
    connect_->setObjectName(QStringLiteral("liveConnect"));
    connect(connect_, &QPushButton::clicked, this, &LivePanel::onConnectClicked);
    record_ = new QPushButton(tr("Record..."), this);
    record_->setObjectName(QStringLiteral("liveRecord"));
    connect(record_, &QPushButton::clicked, this, &LivePanel::onRecordClicked);

    auto* portRow = new QHBoxLayout;
    portRow->addWidget(port_, 1);
    portRow->addWidget(refresh);
    auto* settings = new QFormLayout;
    settings->addRow(tr("Port:"), portRow);
    settings->addRow(tr("Baud:"), baud_);
    settings->addRow(tr("Rate:"), rate_);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(connect_);
    buttons->addWidget(record_);
    settings->addRow(buttons);

    status_ = new QLabel(tr("Not connected"), this);
    status_->setWordWrap(true);

    auto* device = new QGroupBox(tr("Device"), this);
    auto* deviceForm = new QFormLayout(device);
    deviceId_ = valueLabel(device);
    productCode_ = valueLabel(device);
    firmware_ = valueLabel(device);
    deviceBaud_ = valueLabel(device);
    deviceForm->addRow(tr("Device ID:"), deviceId_);
    deviceForm->addRow(tr("Product code:"), productCode_);
    deviceForm->addRow(tr("Firmware:"), firmware_);
    deviceForm->addRow(tr("Baud:"), deviceBaud_);

    auto* counters = new QGroupBox(tr("Counters"), this);
    auto* countersForm = new QFormLayout(counters);
    samplesLabel_ = valueLabel(counters);
    lostLabel_ = valueLabel(counters);
    checksumLabel_ = valueLabel(counters);
    resyncLabel_ = valueLabel(counters);
    countersForm->addRow(tr("Samples:"), samplesLabel_);
    countersForm->addRow(tr("Lost packets:"), lostLabel_);
    countersForm->addRow(tr("Checksum errors:"), checksumLabel_);
    countersForm->addRow(tr("Resyncs:"), resyncLabel_);

    latency_ = new QLabel(tr("estimate lags by %1 s (detector look-ahead)").arg(latency_s(), 0, 'f', 3), this);
    latency_->setObjectName(QStringLiteral("liveLatency"));

    // The live views are made on the first connection (ensureViews): until then the workspace
    // holds only its own plots, which the rest of the window (and its tests) look up by type.
    views_ = new QSplitter(Qt::Vertical, this);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(settings);
    layout->addWidget(status_);
    layout->addWidget(device);
    layout->addWidget(counters);
    layout->addWidget(latency_);
    layout->addWidget(views_, 1);

    plotTimer_ = new QTimer(this);
    plotTimer_->setInterval(kPlotInterval_ms);
    connect(plotTimer_, &QTimer::timeout, this, &LivePanel::redrawSignals);
    estimateTimer_ = new QTimer(this);
    estimateTimer_->setInterval(kEstimateInterval_ms);
    connect(estimateTimer_, &QTimer::timeout, this, &LivePanel::startEstimate);
    connect(&estimate_, &QFutureWatcher<std::shared_ptr<const Result>>::finished, this, &LivePanel::onEstimateDone);
}

void LivePanel::ensureViews()
{
    if (plots_)
        return;
    trajectory_ = new TrajectoryView2D(views_);
    trajectory_->setMinimumHeight(200);
    plots_ = new SignalPlots(views_);
    plots_->setMinimumHeight(200);
    views_->addWidget(trajectory_);
    views_->addWidget(plots_);
}

void LivePanel::wireSession()
{
    connect(session_, &DeviceSession::stateChanged, this, &LivePanel::onStateChanged);
    connect(session_, &DeviceSession::progress, status_, &QLabel::setText);
    connect(session_, &DeviceSession::warning, status_, &QLabel::setText);
    connect(session_, &DeviceSession::deviceIdentified, this, [this](const DeviceInfo& info) {
        deviceId_->setText(info.deviceIdText());
        productCode_->setText(info.productCode);
        firmware_->setText(QStringLiteral("%1.%2.%3")
                               .arg(int(info.firmware.major))
                               .arg(int(info.firmware.minor))
                               .arg(int(info.firmware.revision)));
        deviceBaud_->setText(QString::number(info.baud));
    });
    connect(session_, &DeviceSession::samplesAvailable, this, &LivePanel::onSamplesAvailable);
    connect(session_, &DeviceSession::countersChanged, this, &LivePanel::onCounters);
    connect(session_, &DeviceSession::recordingStarted, this, [this](const RecordingPaths& paths) {
        recordingActive_ = true;
        recordingPath_ = paths.mtb;
        status_->setText(tr("Recording to %1").arg(QDir::toNativeSeparators(paths.mtb)));
        updateButtons();
    });
    connect(session_, &DeviceSession::recordingStopped, this, &LivePanel::onRecordingStopped);
    connect(session_, &DeviceSession::ended, this, &LivePanel::onEnded);
}

void LivePanel::refreshPorts()
{
    const QString current = port_->currentText();
    port_->clear();
    for (const SerialPortDescription& port : availableSerialPorts())
        port_->addItem(port.displayText(), port.portName);
    if (!current.isEmpty())
        port_->setEditText(current);
}

void LivePanel::connectTo(const QString& port)
{
    if (session_->state() != SessionState::Idle)
        return;
    port_->setEditText(port);
    SessionSettings settings;
    settings.portName = port;
    const int baud = baud_->currentData().toInt();
    settings.probeBaudRates = baud == 0;
    settings.baud = baud == 0 ? 115200u : static_cast<std::uint32_t>(baud);
    settings.rate_hz = static_cast<std::uint16_t>(rate_->value());
    if (!recordingPath_.isEmpty() && !recordingActive_) {
        // Asked to record before connecting: record from the first sample on.
        const QFileInfo mtb(recordingPath_);
        settings.recording = {recordingPath_, mtb.dir().filePath(mtb.completeBaseName() + QStringLiteral(".csv"))};
    }
    samples_.clear();
    plotDirty_ = false;
    estimatedSamples_ = 0;
    lastResult_.reset();
    ensureViews();
    trajectory_->clear();
    session_->start(settings);
    plotTimer_->start();
    estimateTimer_->start();
    updateButtons();
}

void LivePanel::disconnectDevice()
{
    if (session_->state() != SessionState::Idle)
        session_->stop();
}

void LivePanel::startRecordingTo(const QString& mtbPath)
{
    if (mtbPath.isEmpty())
        return;
    recordingPath_ = mtbPath;
    if (session_->state() == SessionState::Idle) {
        status_->setText(tr("Recording starts when connected: %1").arg(QDir::toNativeSeparators(mtbPath)));
        updateButtons();
        return;
    }
    const QFileInfo mtb(mtbPath);
    session_->startRecording({mtbPath, mtb.dir().filePath(mtb.completeBaseName() + QStringLiteral(".csv"))});
}

void LivePanel::stopRecording()
{
    if (recordingActive_) {
        session_->stopRecording();
    } else if (!recordingPath_.isEmpty() && session_->state() == SessionState::Idle) {
        recordingPath_.clear();  // a pending request that never started
        status_->setText(tr("Not connected"));
        updateButtons();
    }
}

void LivePanel::onConnectClicked()
{
    if (session_->state() == SessionState::Idle) {
        QString port = port_->currentText().trimmed();
        const int index = port_->findText(port);
        if (index >= 0 && port_->itemData(index).isValid())
            port = port_->itemData(index).toString();
        if (port.isEmpty()) {
            status_->setText(tr("Choose a port or type its path."));
            return;
        }
        connectTo(port);
    } else {
        disconnectDevice();
    }
}

void LivePanel::onRecordClicked()
{
    if (recordingActive_ || (!recordingPath_.isEmpty() && session_->state() == SessionState::Idle)) {
        stopRecording();
        return;
    }
    const QString path = QFileDialog::getSaveFileName(this, tr("Record to"), QDir::homePath(),
                                                      tr("Xsens MT binary (*.mtb)"));
    if (path.isEmpty())
        return;
    startRecordingTo(path.endsWith(QStringLiteral(".mtb"), Qt::CaseInsensitive) ? path
                                                                                   : path + QStringLiteral(".mtb"));
}

void LivePanel::onStateChanged(SessionState state)
{
    switch (state) {
    case SessionState::Idle:
        break;
    case SessionState::Initialising:
        status_->setText(tr("Connecting..."));
        break;
    case SessionState::Streaming:
        if (!recordingActive_)
            status_->setText(tr("Streaming"));
        break;
    case SessionState::Stopping:
        status_->setText(tr("Stopping..."));
        break;
    }
    updateButtons();
}

void LivePanel::onSamplesAvailable()
{
    const std::vector<LiveSample> batch = session_->takeSamples();
    if (batch.empty())
        return;
    samples_.reserve(samples_.size() + batch.size());
    for (const LiveSample& sample : batch)
        samples_.push_back(sample.imu);
    plotDirty_ = true;
}

void LivePanel::onCounters(const DeviceCounters& counters)
{
    samplesLabel_->setText(QString::number(counters.samplesReceived));
    lostLabel_->setText(QString::number(counters.packetsLost));
    checksumLabel_->setText(QString::number(counters.checksumErrors));
    resyncLabel_->setText(QString::number(counters.resyncs));
}

void LivePanel::onRecordingStopped(const RecordingPaths& paths, const QString& error)
{
    recordingActive_ = false;
    if (!error.isEmpty())
        status_->setText(tr("Recording stopped: %1").arg(error));
    else
        status_->setText(tr("Recording saved to %1").arg(QDir::toNativeSeparators(paths.mtb)));
    finishRecording(paths.mtb);
    updateButtons();
}

void LivePanel::onEnded(SessionEnd how, const QString& message)
{
    onSamplesAvailable();
    plotTimer_->stop();
    estimateTimer_->stop();
    redrawSignals();
    startEstimate();
    if (how == SessionEnd::Stopped)
        status_->setText(message.isEmpty() ? tr("Disconnected") : message);
    else
        status_->setText(tr("Session ended: %1").arg(message));
    if (recordingActive_) {
        recordingActive_ = false;
        finishRecording(recordingPath_);
    } else if (!recordingPath_.isEmpty() && !QFileInfo::exists(recordingPath_)) {
        recordingPath_.clear();  // the recording never started
    }
    updateButtons();
}

void LivePanel::finishRecording(const QString& mtbPath)
{
    if (mtbPath.isEmpty() || recordingPath_.isEmpty())
        return;  // already handed on
    recordingPath_.clear();
    if (QFileInfo::exists(mtbPath))
        emit recordingFinished(mtbPath);
}

void LivePanel::redrawSignals()
{
    if (!plotDirty_ || samples_.empty() || !plots_)
        return;
    plotDirty_ = false;
    auto recording = std::make_shared<Recording>();
    recording->source = tr("live").toStdString();
    const double from = samples_.back().time_s - kPlotWindow_s;
    const auto first = std::lower_bound(samples_.begin(), samples_.end(), from,
                                        [](const ImuSample& s, double t) { return s.time_s < t; });
    recording->samples.assign(first, samples_.end());
    plots_->setRecording(std::move(recording));
}

void LivePanel::startEstimate()
{
    if (estimate_.isRunning() || samples_.size() == estimatedSamples_ || samples_.size() < 2)
        return;
    estimatedSamples_ = samples_.size();
    auto recording = std::make_shared<Recording>();
    recording->source = tr("live").toStdString();
    recording->samples = samples_;
    estimate_.setFuture(QtConcurrent::run([recording]() -> std::shared_ptr<const Result> {
        PipelineOutput output = runPipeline(*recording, Parameters{});
        if (!output.error.empty())
            return {};
        return std::make_shared<const Result>(std::move(output.result));
    }));
}

void LivePanel::onEstimateDone()
{
    std::shared_ptr<const Result> result = estimate_.result();
    if (!result || !trajectory_)
        return;
    lastResult_ = result;
    trajectory_->setResult(std::move(result));
    emit trajectoryUpdated();
}

void LivePanel::updateButtons()
{
    const bool idle = session_->state() == SessionState::Idle;
    connect_->setText(idle ? tr("Connect") : tr("Disconnect"));
    port_->setEnabled(idle);
    baud_->setEnabled(idle);
    rate_->setEnabled(idle);
    const bool recording = recordingActive_ || (!recordingPath_.isEmpty() && idle);
    record_->setText(recording ? tr("Stop recording") : tr("Record..."));
}

}  // namespace footpath
