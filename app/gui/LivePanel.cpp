#include "LivePanel.h"

#include "LiveReestimator.h"
#include "LiveViews.h"
#include "PortDiscovery.h"
#include "ReconnectOffer.h"
#include "Recorder.h"
#include "SignalPlots.h"
#include "StanceFlagsPlot.h"
#include "SummaryPanel.h"
#include "TrajectoryView2D.h"
#include "TrajectoryView3D.h"
#include "WarningOverlay.h"
#include "nav/Plausibility.h"
#include "nav/StreamingEstimator.h"

#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <QSplitter>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace footpath {

namespace {

constexpr int kViewInterval_ms = 200;  // at most 5 redraws per second
const char* const kRecordingFolderKey = "live/recordingFolder";

/// Where recordings go: the folder of the last one, else the documents folder.
QString recordingFolder()
{
    const QString last = QSettings().value(QLatin1String(kRecordingFolderKey)).toString();
    if (!last.isEmpty() && QFileInfo(last).isDir())
        return last;
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    return documents.isEmpty() ? QDir::homePath() : documents;
}

void rememberRecordingFolder(const QString& filePath)
{
    QSettings().setValue(QLatin1String(kRecordingFolderKey), QFileInfo(filePath).absolutePath());
}

/// `path`, or with -2, -3, ... before the suffix when that name is taken: never overwrite a walk.
QString freePath(const QString& path)
{
    const QFileInfo file(path);
    QString candidate = path;
    for (int number = 2; QFileInfo::exists(candidate); ++number)
        candidate = file.dir().filePath(QStringLiteral("%1-%2.%3").arg(file.completeBaseName()).arg(number).arg(file.suffix()));
    return candidate;
}

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

/// Moves every tab of `from` to the end of `to`, keeping its label and tool tip.
void moveTabs(QTabWidget* from, QTabWidget* to)
{
    while (from->count() > 0) {
        const QString label = from->tabText(0);
        const QString toolTip = from->tabToolTip(0);
        QWidget* page = from->widget(0);
        from->removeTab(0);
        to->setTabToolTip(to->addTab(page, label), toolTip);
    }
}

}  // namespace

QString defaultRecordingName(const QString& deviceId, const QDateTime& when)
{
    const QString stamp = when.toString(QStringLiteral("yyyy-MM-dd-HHmm"));
    return deviceId.isEmpty() ? QStringLiteral("MTi-%1.mtb").arg(stamp) : QStringLiteral("MTi-%1-%2.mtb").arg(deviceId, stamp);
}

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
    : QWidget(parent), session_(new DeviceSession(serialDevicePortFactory(), this)), reestimator_(new LiveReestimator(this))
{
    connect(reestimator_, &LiveReestimator::finished, this, &LivePanel::adoptReestimate);
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
    port_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    port_->setMinimumContentsLength(8);
    auto* refresh = new QToolButton(this);  // an icon: the dock is often narrow
    refresh->setIcon(style()->standardIcon(QStyle::SP_BrowserReload));
    refresh->setToolTip(tr("Refresh the list of ports"));
    connect(refresh, &QToolButton::clicked, this, &LivePanel::refreshPorts);

    baud_ = new QComboBox(this);
    baud_->setObjectName(QStringLiteral("liveBaud"));
    baud_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    baud_->setMinimumContentsLength(6);
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
    save_ = new QPushButton(tr("Save..."), this);
    save_->setObjectName(QStringLiteral("liveSave"));
    save_->setToolTip(tr("Save the samples received in the last session (kept in memory) as a CSV file and open it "
                         "as a recorded walk: for a session that was not recorded"));
    connect(save_, &QPushButton::clicked, this, &LivePanel::onSaveClicked);

    auto* portRow = new QHBoxLayout;
    portRow->addWidget(port_, 1);
    portRow->addWidget(refresh);
    auto* settings = new QFormLayout;
    settings->setRowWrapPolicy(QFormLayout::WrapLongRows);
    settings->addRow(tr("Port:"), portRow);
    settings->addRow(tr("Baud:"), baud_);
    settings->addRow(tr("Rate:"), rate_);
    // Two rows, so the panel fits a narrow dock.
    auto* buttons = new QGridLayout;
    buttons->addWidget(connect_, 0, 0, 1, 2);
    buttons->addWidget(record_, 1, 0);
    buttons->addWidget(save_, 1, 1);
    settings->addRow(buttons);

    status_ = new QLabel(tr("Not connected"), this);
    status_->setObjectName(QStringLiteral("liveStatus"));
    status_->setWordWrap(true);
    QFont stateFont = status_->font();
    stateFont.setBold(true);
    status_->setFont(stateFont);
    // Where a failed connection says why: a red banner under the state line, not small print.
    error_ = new QLabel(this);
    error_->setObjectName(QStringLiteral("liveError"));
    error_->setWordWrap(true);
    error_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    error_->setStyleSheet(QStringLiteral("QLabel { background: #fde2e1; color: #7a1010; border: 1px solid #e0a0a0; "
                                         "border-radius: 4px; padding: 6px; }"));
    error_->hide();
    reconnect_ = new ReconnectOffer(this);
    connect(reconnect_, &ReconnectOffer::reconnectRequested, this, &LivePanel::onReconnect);

    auto* device = new QGroupBox(tr("Device"), this);
    auto* deviceForm = new QFormLayout(device);
    deviceForm->setRowWrapPolicy(QFormLayout::WrapLongRows);
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
    countersForm->setRowWrapPolicy(QFormLayout::WrapLongRows);
    samplesLabel_ = valueLabel(counters);
    lostLabel_ = valueLabel(counters);
    checksumLabel_ = valueLabel(counters);
    resyncLabel_ = valueLabel(counters);
    notShownLabel_ = valueLabel(counters);
    notShownLabel_->setObjectName(QStringLiteral("liveNotShown"));
    notShownLabel_->setToolTip(tr("Samples the views could not keep up with (the window was busy for longer "
                                  "than the display queue holds). They are in the recording all the same."));
    countersForm->addRow(tr("Samples:"), samplesLabel_);
    countersForm->addRow(tr("Lost packets:"), lostLabel_);
    countersForm->addRow(tr("Checksum errors:"), checksumLabel_);
    countersForm->addRow(tr("Resyncs:"), resyncLabel_);
    countersForm->addRow(tr("Not shown:"), notShownLabel_);
    countersForm->setRowVisible(notShownLabel_, false);  // only once it happens
    countersForm_ = countersForm;

    // The views sit here until the workspace takes them (moveViewsInto).
    viewArea_ = new QSplitter(Qt::Vertical, this);
    views_ = new LiveViews(viewArea_);
    viewArea_->addWidget(views_->trajectoryTabs());
    viewArea_->addWidget(views_->signalTabs());

    // Scrolls rather than squeezes when the dock is short: the rows stay readable.
    auto* content = new QWidget;
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // rows wrap to the dock's width instead
    scroll->setFrameShape(QFrame::NoFrame);
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->addWidget(scroll);
    auto* layout = new QVBoxLayout(content);
    contentLayout_ = layout;
    layout->addLayout(settings);
    layout->addWidget(status_);
    layout->addWidget(error_);
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
    updateNotice();
}

QWidget* LivePanel::buildEstimateBox()
{
    auto* box = new QGroupBox(tr("Estimate"), this);
    auto* form = new QFormLayout(box);
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    latency_ = valueLabel(box);
    latency_->setObjectName(QStringLiteral("liveLatency"));
    latency_->setToolTip(tr("The stance detector looks this far ahead (its windows are centred on each sample, and a "
                            "stance is confirmed once it has lasted the minimum duration), so the estimate trails the "
                            "sensor by up to this delay."));
    estimateState_ = valueLabel(box);
    estimateState_->setObjectName(QStringLiteral("liveEstimateState"));
    estimateState_->setWordWrap(true);
    steps_ = valueLabel(box);
    steps_->setObjectName(QStringLiteral("liveSteps"));
    distance_ = valueLabel(box);
    distance_->setObjectName(QStringLiteral("liveDistance"));
    duration_ = valueLabel(box);
    duration_->setObjectName(QStringLiteral("liveDuration"));
    endToStart_ = valueLabel(box);
    endToStart_->setObjectName(QStringLiteral("liveEndToStart"));
    endToStart_->setToolTip(tr("Horizontal distance from the start to where the foot is now"));
    warnings_ = valueLabel(box);
    warnings_->setObjectName(QStringLiteral("liveWarnings"));
    warnings_->setWordWrap(true);
    form->addRow(tr("Latency:"), latency_);
    form->addRow(tr("State:"), estimateState_);
    form->addRow(tr("Steps:"), steps_);
    form->addRow(tr("Distance:"), distance_);
    form->addRow(tr("Duration:"), duration_);
    form->addRow(tr("End to start:"), endToStart_);
    form->addRow(tr("Warnings:"), warnings_);
    return box;
}

void LivePanel::moveViewsInto(QTabWidget* trajectoryTabs, QTabWidget* signalTabs)
{
    moveTabs(views_->trajectoryTabs(), trajectoryTabs);
    moveTabs(views_->signalTabs(), signalTabs);
    viewArea_->hide();
    contentLayout_->addStretch(1);
    workspaceTabs_ = {QPointer<QTabWidget>(trajectoryTabs), QPointer<QTabWidget>(signalTabs)};
    for (QTabWidget* tabs : workspaceTabs_)
        connect(tabs, &QTabWidget::currentChanged, this, &LivePanel::showSummarySource);
}

void LivePanel::linkSummary(SummaryPanel* summary)
{
    summary_ = summary;
    connect(this, &LivePanel::trajectoryUpdated, this, &LivePanel::showSummarySource);
    showSummarySource();
}

bool LivePanel::liveViewShown() const
{
    const QWidget* liveViews[] = {views_->trajectory2D(), views_->trajectory3D(), views_->signalPlots(),
                                  views_->stanceFlags()};
    for (const QTabWidget* tabs : workspaceTabs_) {
        const QWidget* current = tabs ? tabs->currentWidget() : nullptr;
        for (const QWidget* view : liveViews)
            if (current != nullptr && (current == view || current->isAncestorOf(view)))
                return true;
    }
    return false;
}

void LivePanel::showSummarySource()
{
    publishStatusLine();
    if (summary_ == nullptr)
        return;
    if (liveViewShown())
        summary_->showLive(lastResult_);
    else
        summary_->showRecorded();
}

QString LivePanel::statusLine() const
{
    return summaryLine_.isEmpty() ? tr("Live session: %1").arg(statusText()) : summaryLine_;
}

void LivePanel::publishStatusLine()
{
    emit liveStatusChanged(liveViewShown() ? statusLine() : QString());
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
        sessionRecordedFromStart_ = sessionRecordedFromStart_ || received_.empty();
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

bool LivePanel::connectTo(const QString& port, SessionEnding ending)
{
    if (session_->state() != SessionState::Idle || !mayEndSession(ending))
        return false;
    reconnect_->withdraw();
    port_->setEditText(port);
    lastPort_ = port;
    SessionSettings settings;
    settings.portName = port;
    const int baud = baud_->currentData().toInt();
    settings.probeBaudRates = baud == 0;
    settings.baud = baud == 0 ? 115200u : static_cast<std::uint32_t>(baud);
    settings.rate_hz = static_cast<std::uint16_t>(rate_->value());
    settings.displayQueueSamples = displayQueueSamples_;
    if (!recordingPath_.isEmpty() && !recordingActive_)
        settings.recording = recordingPathsFor(recordingPath_);  // asked before connecting: from the first sample on
    received_.clear();
    samplesSaved_ = false;
    sessionRecordedFromStart_ = !settings.recording.isEmpty();
    error_->hide();
    restartEstimate();
    lastResult_.reset();
    views_->clear();
    summaryLine_.clear();
    views_->setSummaryLine({});
    session_->start(settings);
    viewTimer_->start();
    updateButtons();
    emit sessionStarted();
    return true;
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
    if (received_.empty() || !params_.validate().empty()) {
        restartEstimate();  // nothing to catch up with, or nothing will be estimated
        refreshViews(true);
        return;
    }
    // The old estimator goes on with the samples arriving meanwhile; the new one catches up with
    // them when it arrives (adoptReestimate).
    std::vector<ImuSample> samples;
    samples.reserve(received_.size());
    for (const LiveSample& sample : received_)
        samples.push_back(sample.imu);
    reestimateFinishes_ = session_->state() == SessionState::Idle;
    reestimator_->start(std::move(samples), params_, reestimateFinishes_);
    showEstimateFigures();
}

bool LivePanel::isReestimating() const
{
    return reestimator_->isRunning();
}

void LivePanel::adoptReestimate(std::shared_ptr<StreamingEstimator> estimator, std::size_t samples)
{
    estimator_ = std::move(estimator);
    for (std::size_t k = samples; k < received_.size(); ++k)
        estimator_->push(received_[k].imu);
    if (session_->state() == SessionState::Idle && !reestimateFinishes_)
        estimator_->finish();  // the session ended while it ran
    views_->restartPath();
    refreshViews(true);
}

void LivePanel::restartEstimate()
{
    reestimator_->cancel();  // a re-estimate of other samples or parameters must not take over
    estimator_ = std::make_shared<StreamingEstimator>(params_);
    views_->restartPath();
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
            status_->setText(tr("Not connected"));
            showError(tr("Choose a port or type its path."));
            return;
        }
        connectTo(port);  // asks about unsaved samples first
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
    const QString path = QFileDialog::getSaveFileName(this, tr("Record to"), suggestedRecordingPath(),
                                                      tr("Xsens MT binary (*.mtb)"));
    if (path.isEmpty())
        return;
    rememberRecordingFolder(path);
    startRecordingTo(path.endsWith(QStringLiteral(".mtb"), Qt::CaseInsensitive) ? path
                                                                                   : path + QStringLiteral(".mtb"));
}

QString LivePanel::suggestedRecordingPath() const
{
    const std::uint64_t id = session_->deviceInfo().deviceId;
    const QString name = defaultRecordingName(id != 0 ? session_->deviceInfo().deviceIdText() : QString(),
                                              QDateTime::currentDateTime());
    return freePath(QDir(recordingFolder()).filePath(name));
}

bool LivePanel::hasUnsavedSamples() const
{
    return !received_.empty() && !sessionRecordedFromStart_ && !samplesSaved_;
}

QString LivePanel::errorText() const
{
    return error_->isHidden() ? QString() : error_->text();
}

QString LivePanel::statusText() const
{
    return status_->text();
}

QString LivePanel::saveSamplesTo(const QString& csvPath)
{
    const QString error = writeSamplesCsv(csvPath, received_);
    if (!error.isEmpty()) {
        showError(error);
        return error;
    }
    samplesSaved_ = true;
    status_->setText(tr("Samples saved to %1").arg(QDir::toNativeSeparators(csvPath)));
    emit recordingFinished(csvPath);  // opened as a recorded walk, as a finished recording is
    return {};
}

void LivePanel::onSaveClicked()
{
    const QString suggested = QFileInfo(suggestedRecordingPath()).completeBaseName() + QStringLiteral(".csv");
    QString path = QFileDialog::getSaveFileName(this, tr("Save samples"), QDir(recordingFolder()).filePath(suggested),
                                                tr("CSV (*.csv)"));
    if (path.isEmpty())
        return;
    if (!path.endsWith(QStringLiteral(".csv"), Qt::CaseInsensitive))
        path += QStringLiteral(".csv");
    rememberRecordingFolder(path);
    saveSamplesTo(path);
    updateButtons();
}

bool LivePanel::mayEndSession(SessionEnding ending)
{
    return !hasUnsavedSamples() || confirmDiscardingSamples(ending);
}

/// A new session (or quitting) clears the samples in memory: the user saves them first or agrees to
/// lose them.
bool LivePanel::confirmDiscardingSamples(SessionEnding ending)
{
    const QString count = QString::number(received_.size());
    QString question;
    switch (ending) {
    case SessionEnding::Connect:
        question = tr("The last session's %1 samples were not recorded. Save them before connecting again?").arg(count);
        break;
    case SessionEnding::Reconnect:
        question = tr("The %1 samples received before the port went away were not recorded. Reconnecting starts a new "
                      "session without them. Save them before reconnecting?")
                       .arg(count);
        break;
    case SessionEnding::Quit:
        question = tr("The live session's %1 samples were not recorded. Save them before quitting?").arg(count);
        break;
    }
    const QMessageBox::StandardButton answer =
        QMessageBox::question(this, tr("Unsaved samples"), question,
                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        onSaveClicked();
    return answer == QMessageBox::Discard || (answer == QMessageBox::Save && samplesSaved_);
}

void LivePanel::showError(const QString& message)
{
    error_->setText(message);
    error_->setVisible(!message.isEmpty());
}

/// What the empty live views say: why there is nothing to see yet.
void LivePanel::updateNotice()
{
    if (!received_.empty()) {
        views_->setNotice({});
        return;
    }
    switch (session_->state()) {
    case SessionState::Idle:
        views_->setNotice(error_->isHidden() ? tr("Not connected: choose a port and Connect (Live input panel)")
                                             : tr("Not connected: %1").arg(error_->text()));
        break;
    case SessionState::Initialising:
        views_->setNotice(tr("Connecting to %1...").arg(QDir::toNativeSeparators(lastPort_)));
        break;
    case SessionState::Streaming:
    case SessionState::Stopping:
        views_->setNotice(tr("Connected: waiting for samples..."));
        break;
    }
}

void LivePanel::onReconnect()
{
    if (!lastPort_.isEmpty())
        connectTo(lastPort_, SessionEnding::Reconnect);
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
    updateNotice();
    updateButtons();
    publishStatusLine();
}

void LivePanel::onSamplesAvailable()
{
    std::vector<LiveSample> batch = session_->takeSamples();
    if (batch.empty())
        return;
    const bool first = received_.empty();
    received_.reserve(received_.size() + batch.size());
    for (LiveSample& sample : batch) {
        if (estimator_)
            estimator_->push(sample.imu);
        received_.push_back(std::move(sample));
    }
    viewsDirty_ = true;
    if (first)
        updateNotice();
}

void LivePanel::onCounters(const DeviceCounters& counters)
{
    samplesLabel_->setText(QString::number(counters.samplesReceived));
    lostLabel_->setText(QString::number(counters.packetsLost));
    checksumLabel_->setText(QString::number(counters.checksumErrors));
    resyncLabel_->setText(QString::number(counters.resyncs));
    notShownLabel_->setText(QString::number(counters.samplesNotShown));
    countersForm_->setRowVisible(notShownLabel_, counters.samplesNotShown > 0);
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
        status_->setText(received_.empty() ? tr("Not connected") : tr("Disconnected: the session failed"));
    if (how == SessionEnd::Failed)
        showError(message.isEmpty() ? tr("The connection failed.") : message);
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
    showEstimateFigures();
    updateNotice();
    updateButtons();
    publishStatusLine();
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
    if (std::shared_ptr<const Result> path = views_->showPath(estimator_->result(), currentWarnings(), force)) {
        lastResult_ = std::move(path);
        emit trajectoryUpdated();
    }
    showEstimateFigures();
}

void LivePanel::showEstimateFigures()
{
    latency_->setText(tr("%1 s").arg(latency_s(), 0, 'f', 3));
    if (!estimator_ || received_.empty()) {
        estimateState_->setText(session_->state() == SessionState::Idle ? tr("Not connected") : tr("Waiting for samples"));
        return;
    }
    if (!estimator_->error().empty())  // parameters it refused: not aligning, not estimating
        estimateState_->setText(tr("No live estimate: %1").arg(QString::fromStdString(estimator_->error())));
    else if (reestimator_->isRunning())
        estimateState_->setText(tr("Re-estimating with the new parameters (the old estimate is shown meanwhile)"));
    else if (session_->state() == SessionState::Idle && estimator_->pendingSamples() == 0 && estimator_->aligned())
        estimateState_->setText(tr("Complete: every sample estimated, as the offline analysis does"));
    else if (!estimator_->aligned())
        estimateState_->setText(tr("Aligning: keep the foot still for %1 s (a walk already under way is aligned at "
                                   "its first stance)").arg(params_.alignment_s, 0, 'g', 3));
    else if (!estimator_->result().time_s.empty())
        estimateState_->setText(tr("Estimating (%1 s behind)")
                                    .arg(received_.back().imu.time_s - estimator_->result().time_s.back(), 0, 'f', 3));
    showLiveSummary();
}

std::vector<PlausibilityWarning> LivePanel::currentWarnings() const
{
    // While streaming the checks run on the estimate so far; at the end the estimator has them.
    const Result& result = estimator_->result();
    return session_->state() == SessionState::Idle || result.time_s.empty() ? result.warnings
                                                                            : checkPlausibility(result, params_);
}

/// The live session's own figures in the panel and over the live path.
void LivePanel::showLiveSummary()
{
    const Result& result = estimator_->result();
    const Summary& summary = result.summary;
    steps_->setText(QString::number(summary.steps));
    distance_->setText(tr("%1 m").arg(summary.pathLength_m, 0, 'f', 2));
    duration_->setText(tr("%1 s").arg(received_.back().imu.time_s - received_.front().imu.time_s, 0, 'f', 1));
    endToStart_->setText(result.time_s.empty() ? QStringLiteral("-") : tr("%1 m").arg(summary.endToStart_m, 0, 'f', 2));
    const std::vector<PlausibilityWarning> warnings = currentWarnings();
    QStringList kinds;
    for (const PlausibilityWarning& warning : warnings)
        if (!kinds.contains(warningLabel(warning.kind)))
            kinds << warningLabel(warning.kind);
    warnings_->setText(warnings.empty() ? tr("none") : tr("%1 (%2)").arg(warnings.size()).arg(kinds.join(QStringLiteral(", "))));
    QStringList messages;
    for (const PlausibilityWarning& warning : warnings)
        messages << QString::fromStdString(warning.message);
    warnings_->setToolTip(messages.join(QStringLiteral("\n\n")));
    summaryLine_ = tr("Live: %1 steps, %2 m, %3 s, end to start %4 m, warnings: %5")
                       .arg(summary.steps)
                       .arg(summary.pathLength_m, 0, 'f', 1)
                       .arg(received_.back().imu.time_s - received_.front().imu.time_s, 0, 'f', 0)
                       .arg(summary.endToStart_m, 0, 'f', 1)
                       .arg(warnings_->text());
    views_->setSummaryLine(summaryLine_);
    publishStatusLine();
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
    save_->setEnabled(idle && !received_.empty());
}

}  // namespace footpath
