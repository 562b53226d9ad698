#include "LivePanel.h"

#include "LiveViews.h"
#include "PortDiscovery.h"
#include "ReconnectOffer.h"
#include "nav/StreamingEstimator.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace footpath {

namespace {

constexpr int kViewInterval_ms = 200;  // at most 5 redraws per second

QLabel* valueLabel(QWidget* parent)
{
    auto* label = new QLabel(QStringLiteral("-"), parent);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

RecordingPaths recordingPathsFor(const QString& mtbPath)
{
    const QFileInfo mtb(mtbPath);
    return {mtbPath, mtb.dir().filePath(mtb.completeBaseName() + QStringLiteral(".csv"))};
}

/// Moves every tab of `from` to the end of `to`, keeping its label.
void moveTabs(QTabWidget* from, QTabWidget* to)
{
    while (from->count() > 0) {
        const QString label = from->tabText(0);
        QWidget* page = from->widget(0);
        from->removeTab(0);
        to->addTab(page, label);
    }
}

}  // namespace

QString continuationPath(const QString& mtbPath)
{
    const QFileInfo mtb(mtbPath);
    QString stem = mtb.completeBaseName();
    int number = 2;
    static const QRegularExpression numbered(QStringLiteral("^(.*)-(\\d+)$"));
    if (const QRegularExpressionMatch match = numbered.match(stem); match.hasMatch()) {
        stem = match.captured(1);
        number = match.captured(2).toInt() + 1;
    }
    for (;; ++number) {
        const QString base = mtb.dir().filePath(QStringLiteral("%1-%2").arg(stem).arg(number));
        if (!QFileInfo::exists(base + QStringLiteral(".mtb")) && !QFileInfo::exists(base + QStringLiteral(".csv")))
            return base + QStringLiteral(".mtb");
    }
}

LivePanel::LivePanel(QWidget* parent)
    : QWidget(parent), session_(new DeviceSession(serialDevicePortFactory(), this))
{
    buildUi();
    wireSession();
    refreshPorts();
    updateButtons();
}

LivePanel::~LivePanel() = default;

double LivePanel::latency_s() const
{
    return StreamingEstimator::latency_s(params_);
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
    reconnect_ = new ReconnectOffer(this);
    connect(reconnect_, &ReconnectOffer::reconnectRequested, this, &LivePanel::onReconnect);

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

    // The views sit here until the workspace takes them (moveViewsInto).
    viewArea_ = new QSplitter(Qt::Vertical, this);
    views_ = new LiveViews(viewArea_);
    viewArea_->addWidget(views_->trajectoryTabs());
    viewArea_->addWidget(views_->signalTabs());

    // Scrolls rather than squeezes when the dock is short: the rows stay readable.
    auto* content = new QWidget;
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->addWidget(scroll);
    auto* layout = new QVBoxLayout(content);
    contentLayout_ = layout;
    layout->addLayout(settings);
    layout->addWidget(status_);
    layout->addWidget(reconnect_);
    layout->addWidget(device);
    layout->addWidget(counters);
    layout->addWidget(buildEstimateBox());
    layout->addWidget(viewArea_, 1);
    scroll->setWidget(content);

    viewTimer_ = new QTimer(this);
    viewTimer_->setInterval(kViewInterval_ms);
    connect(viewTimer_, &QTimer::timeout, this, [this] { refreshViews(); });
    showEstimateFigures();
}

QWidget* LivePanel::buildEstimateBox()
{
    auto* box = new QGroupBox(tr("Estimate"), this);
    auto* form = new QFormLayout(box);
    latency_ = valueLabel(box);
    latency_->setObjectName(QStringLiteral("liveLatency"));
    latency_->setToolTip(tr("The stance detector looks this far ahead (its windows are centred on each sample, and a "
                            "stance is confirmed once it has lasted the minimum duration), so the estimate trails the "
                            "sensor by up to this delay."));
    estimateState_ = valueLabel(box);
    estimateState_->setWordWrap(true);
    steps_ = valueLabel(box);
    distance_ = valueLabel(box);
    form->addRow(tr("Latency:"), latency_);
    form->addRow(tr("State:"), estimateState_);
    form->addRow(tr("Steps:"), steps_);
    form->addRow(tr("Distance:"), distance_);
    return box;
}

void LivePanel::moveViewsInto(QTabWidget* trajectoryTabs, QTabWidget* signalTabs)
{
    moveTabs(views_->trajectoryTabs(), trajectoryTabs);
    moveTabs(views_->signalTabs(), signalTabs);
    viewArea_->hide();
    contentLayout_->addStretch(1);
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
    reconnect_->withdraw();
    port_->setEditText(port);
    lastPort_ = port;
    SessionSettings settings;
    settings.portName = port;
    const int baud = baud_->currentData().toInt();
    settings.probeBaudRates = baud == 0;
    settings.baud = baud == 0 ? 115200u : static_cast<std::uint32_t>(baud);
    settings.rate_hz = static_cast<std::uint16_t>(rate_->value());
    if (!recordingPath_.isEmpty() && !recordingActive_)
        settings.recording = recordingPathsFor(recordingPath_);  // asked before connecting: from the first sample on
    received_.clear();
    restartEstimate();
    lastResult_.reset();
    views_->clear();
    session_->start(settings);
    viewTimer_->start();
    updateButtons();
    emit sessionStarted();
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
    session_->startRecording(recordingPathsFor(mtbPath));
}

void LivePanel::stopRecording()
{
    if (recordingActive_) {
        recordingStopAsked_ = true;
        session_->stopRecording();
    } else if (!recordingPath_.isEmpty() && session_->state() == SessionState::Idle) {
        recordingPath_.clear();  // a pending request that never started
        status_->setText(tr("Not connected"));
        updateButtons();
    }
}

void LivePanel::setParameters(const Parameters& params)
{
    if (params == params_)
        return;
    params_ = params;
    views_->setParameters(params_);
    if (!estimator_)
        return;
    restartEstimate();
    for (const LiveSample& sample : received_)
        estimator_->push(sample.imu);
    if (session_->state() == SessionState::Idle)
        estimator_->finish();
    refreshViews(true);
}

void LivePanel::restartEstimate()
{
    estimator_ = std::make_unique<StreamingEstimator>(params_);
    if (!estimator_->error().empty())
        status_->setText(tr("No live estimate: %1").arg(QString::fromStdString(estimator_->error())));
    viewsDirty_ = true;
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

void LivePanel::onReconnect()
{
    if (!lastPort_.isEmpty())
        connectTo(lastPort_);
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
    std::vector<LiveSample> batch = session_->takeSamples();
    if (batch.empty())
        return;
    received_.reserve(received_.size() + batch.size());
    for (LiveSample& sample : batch) {
        if (estimator_)
            estimator_->push(sample.imu);
        received_.push_back(std::move(sample));
    }
    viewsDirty_ = true;
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
    // Closed without being asked and without a disk error: the session is ending under it.
    recordingCutBySessionEnd_ = !recordingStopAsked_ && error.isEmpty();
    recordingStopAsked_ = false;
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
    viewTimer_->stop();
    if (estimator_)
        estimator_->finish();  // the tail is decided as the offline analysis decides it
    refreshViews(true);
    if (how == SessionEnd::Stopped)
        status_->setText(message.isEmpty() ? tr("Disconnected") : message);
    else if (how == SessionEnd::Vanished)
        status_->setText(tr("Disconnected: the port went away."));  // the reconnect offer has the details
    else
        status_->setText(tr("Session ended: %1").arg(message));
    const bool recordingCut = recordingActive_ || recordingCutBySessionEnd_;
    recordingCutBySessionEnd_ = false;
    if (recordingActive_) {
        recordingActive_ = false;
        finishRecording(recordingPath_);
    } else if (!recordingPath_.isEmpty() && !QFileInfo::exists(recordingPath_)) {
        recordingPath_.clear();  // the recording never started
    }
    if (how == SessionEnd::Vanished) {
        QString continuation;
        if (recordingCut && !lastRecordingPath_.isEmpty()) {
            recordingPath_ = continuationPath(lastRecordingPath_);
            continuation = QDir::toNativeSeparators(recordingPath_);
        }
        reconnect_->offer(lastPort_, message, continuation);
    }
    updateButtons();
}

void LivePanel::finishRecording(const QString& mtbPath)
{
    if (mtbPath.isEmpty() || recordingPath_.isEmpty())
        return;  // already handed on
    recordingPath_.clear();
    lastRecordingPath_ = mtbPath;
    if (QFileInfo::exists(mtbPath))
        emit recordingFinished(mtbPath);
}

void LivePanel::refreshViews(bool force)
{
    if (!estimator_ || (!viewsDirty_ && !force))
        return;
    viewsDirty_ = false;
    views_->showSignals(received_, estimator_->result());
    if (std::shared_ptr<const Result> path = views_->showPath(estimator_->result(), force)) {
        lastResult_ = std::move(path);
        emit trajectoryUpdated();
    }
    showEstimateFigures();
}

void LivePanel::showEstimateFigures()
{
    latency_->setText(tr("%1 s").arg(latency_s(), 0, 'f', 3));
    if (!estimator_ || received_.empty()) {
        estimateState_->setText(tr("Waiting for samples"));
        return;
    }
    if (session_->state() == SessionState::Idle && estimator_->pendingSamples() == 0 && estimator_->aligned())
        estimateState_->setText(tr("Complete: every sample estimated, as the offline analysis does"));
    else if (!estimator_->aligned())
        estimateState_->setText(tr("Aligning: keep the foot still for the first %1 s").arg(params_.alignment_s, 0, 'g', 3));
    else if (!estimator_->result().time_s.empty())
        estimateState_->setText(tr("Estimating, %1 s behind the sensor")
                                    .arg(received_.back().imu.time_s - estimator_->result().time_s.back(), 0, 'f', 3));
    const Summary& summary = estimator_->result().summary;
    steps_->setText(QString::number(summary.steps));
    distance_->setText(tr("%1 m").arg(summary.pathLength_m, 0, 'f', 2));
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
