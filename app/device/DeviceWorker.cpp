#include "DeviceWorker.h"

#include "xbus/MtData2.h"
#include "xbus/XbusControl.h"

#include <QStringList>

namespace footpath {

namespace {

constexpr int kCountersInterval_ms = 200;
constexpr int kSyncInterval_ms = 1000;  ///< recordings reach the disk at least this often
constexpr qint64 kRepeatedWarningInterval_ms = 1000;

QByteArray frameBytes(const XbusMessage& message)
{
    const std::vector<std::uint8_t> frame = encodeFrame(message);
    return QByteArray(reinterpret_cast<const char*>(frame.data()), static_cast<int>(frame.size()));
}

QString qs(const std::string& text)
{
    return QString::fromStdString(text);
}

}  // namespace

DeviceWorker::DeviceWorker(DevicePortFactory factory, LiveSampleQueue& queue, QObject* parent)
    : QObject(parent), factory_(std::move(factory)), queue_(queue)
{
    replyTimer_.setSingleShot(true);
    replyTimer_.setTimerType(Qt::PreciseTimer);  // a coarse timer may fire 5 % early
    connect(&replyTimer_, &QTimer::timeout, this, &DeviceWorker::onReplyTimeout);
    countersTimer_.setInterval(kCountersInterval_ms);
    connect(&countersTimer_, &QTimer::timeout, this, &DeviceWorker::emitCounters);
    syncTimer_.setInterval(kSyncInterval_ms);
    connect(&syncTimer_, &QTimer::timeout, this, [this] {
        if (recorder_.isOpen() && !recorder_.sync())
            recordingFailed(recorder_.error());
    });
}

DeviceWorker::~DeviceWorker()
{
    shutdown();
}

// ---- start ------------------------------------------------------------------------------

void DeviceWorker::start(const SessionSettings& settings)
{
    if (state_ != SessionState::Idle) {
        emit warning(tr("a session is already running on %1").arg(settings_.portName));
        return;
    }
    settings_ = settings;
    info_ = DeviceInfo{};
    info_.portName = settings.portName;
    counters_ = DeviceCounters{};
    queue_.reset(settings.displayQueueSamples);
    if (!settings.recording.isEmpty()) {
        startRecording(settings.recording);  // a bad path is reported before any waiting
        if (!recorder_.isOpen()) {
            emit ended(SessionEnd::Failed, recorder_.error());
            return;
        }
    }
    if (openPort())
        beginInit();
}

bool DeviceWorker::openPort()
{
    port_ = factory_();
    wirePort();
    bauds_ = {settings_.baud};
    if (settings_.probeBaudRates)
        for (std::uint32_t baud : xbusProbeBaudRates())
            if (baud != settings_.baud)
                bauds_.push_back(baud);
    baudIndex_ = 0;
    if (port_->open(settings_.portName, currentBaud()))
        return true;
    QString hint;
    if (port_->errorString().contains(QLatin1String("ermission")))
        hint = tr(" (is your user allowed to use serial ports, e.g. in the dialout group?)");
    const QString message =
        tr("cannot open %1: %2%3").arg(settings_.portName, port_->errorString(), hint);
    releasePort();
    if (recorder_.isOpen()) {
        recorder_.discard();
        emit recordingStopped(recorder_.paths(), tr("nothing was recorded: %1").arg(message));
    }
    emit ended(SessionEnd::Failed, message);
    return false;
}

void DeviceWorker::wirePort()
{
    connect(port_.get(), &DevicePort::readyRead, this, &DeviceWorker::onReadyRead);
    connect(port_.get(), &DevicePort::failed, this, &DeviceWorker::onPortFailed);
}

void DeviceWorker::resetStream()
{
    decoder_.reset();
    rawPending_.clear();
    rawPendingOffset_ = 0;
    lastMessageEnd_ = 0;
    bytesWithoutFrames_ = false;
}

/// §4.2: GoToConfig, ReqDID, ReqProductCode, ReqFWRev, SetOutputConfiguration, GoToMeasurement.
void DeviceWorker::beginInit()
{
    info_.requestedOutput = footpathOutputConfiguration(settings_.rate_hz);
    requests_ = {
        {goToConfigMessage(), XbusMid::GoToConfigAck},
        {reqDeviceIdMessage(), XbusMid::DeviceId},
        {reqProductCodeMessage(), XbusMid::ProductCode},
        {reqFirmwareRevMessage(), XbusMid::FirmwareRev},
        {*setOutputConfigurationMessage(info_.requestedOutput), XbusMid::OutputConfiguration},
        {goToMeasurementMessage(), XbusMid::GoToMeasurementAck},
    };
    requestIndex_ = 0;
    tries_ = 0;
    resetStream();
    assembler_ = SampleAssembler(settings_.rate_hz);
    setState(SessionState::Initialising);
    countersTimer_.start();
    sendRequest();
}

// ---- requests, timeouts, retries ----------------------------------------------------------

int DeviceWorker::currentTimeout() const
{
    const DeviceTimeouts& t = settings_.timeouts;
    if (requestIndex_ > 0)
        return t.reply_ms;
    return baudIndex_ == 0 ? t.goToConfig_ms : t.probe_ms;
}

int DeviceWorker::currentTries() const
{
    // The configured baud gets every try; a probed one a single short look, as XSP's scanner.
    return requestIndex_ == 0 && baudIndex_ > 0 ? 1 : settings_.timeouts.tries;
}

QString DeviceWorker::requestName() const
{
    return qs(xbusMidName(requests_.at(requestIndex_).message.mid));
}

void DeviceWorker::sendRequest()
{
    ++tries_;
    emit progress(tr("%1 at %2 baud on %3 (try %4 of %5)")
                      .arg(requestName())
                      .arg(currentBaud())
                      .arg(settings_.portName)
                      .arg(tries_)
                      .arg(currentTries()));
    if (!port_->write(frameBytes(requests_.at(requestIndex_).message))) {
        failInit(tr("cannot write to %1: %2").arg(settings_.portName, port_->errorString()));
        return;
    }
    replyTimer_.start(currentTimeout());
}

/// After a WakeUp the device listens: ask again at once instead of waiting out the timeout.
void DeviceWorker::resendNow()
{
    --tries_;  // the try that met a booting device does not count
    replyTimer_.stop();
    sendRequest();
}

void DeviceWorker::onReplyTimeout()
{
    if (state_ == SessionState::Stopping) {
        finishStop();  // no acknowledgement: close anyway, the data is safe
        return;
    }
    if (tries_ < currentTries()) {
        sendRequest();
        return;
    }
    if (requestIndex_ == 0 && tryNextBaud())
        return;
    failInit(noAnswerMessage());
}

bool DeviceWorker::tryNextBaud()
{
    if (baudIndex_ + 1 >= bauds_.size())
        return false;
    ++baudIndex_;
    tries_ = 0;
    resetStream();
    if (!port_->setBaudRate(currentBaud())) {
        emit warning(tr("%1 does not support %2 baud").arg(settings_.portName).arg(currentBaud()));
        return tryNextBaud();
    }
    sendRequest();
    return true;
}

QString DeviceWorker::noAnswerMessage() const
{
    const QString port = settings_.portName;
    if (requestIndex_ > 0)
        return tr("no answer to %1 at %2 baud on %3 after %4 tries of %5 ms: the device answered before, "
                  "so it may have been unplugged or reset")
            .arg(requestName())
            .arg(currentBaud())
            .arg(port)
            .arg(currentTries())
            .arg(currentTimeout());
    const QString garbage = bytesWithoutFrames_
                                ? tr(" (bytes arrived, but never a valid Xbus message: another device, or a baud "
                                     "rate outside the list?)")
                                : QString();
    if (bauds_.size() == 1)
        return tr("no answer to GoToConfig at %1 baud on %2: is the device powered and is the baud right?%3")
            .arg(settings_.baud)
            .arg(port, garbage);
    QStringList others;
    for (std::size_t i = 1; i < bauds_.size(); ++i)
        others << QString::number(bauds_[i]);
    return tr("no answer to GoToConfig at %1 baud on %2, nor at %3 baud: is the device powered, and is this "
              "its port?%4")
        .arg(settings_.baud)
        .arg(port, others.join(QLatin1String(", ")), garbage);
}

// ---- incoming bytes -----------------------------------------------------------------------

void DeviceWorker::onReadyRead()
{
    if (!port_)
        return;
    const QByteArray bytes = port_->readAll();
    if (bytes.isEmpty())
        return;
    counters_.bytesReceived += static_cast<std::uint64_t>(bytes.size());
    countersDirty_ = true;
    rawPending_.append(bytes);
    decoder_.feed(reinterpret_cast<const std::uint8_t*>(bytes.constData()), static_cast<std::size_t>(bytes.size()));
    XbusMessage message;
    while (port_ && decoder_.next(message)) {
        lastMessageEnd_ = decoder_.pendingOffset();  // next() has just stepped past the message
        dispatch(message);
    }
    if (state_ == SessionState::Initialising) {
        bytesWithoutFrames_ = bytesWithoutFrames_ || decoder_.stats().framesDecoded == 0;
        flushRaw(decoder_.pendingOffset());  // init traffic is not recorded: dropped here
    } else if (state_ == SessionState::Streaming) {
        deliverBatch();
        flushRaw(recordableEnd());
    }
    updateCounters();
}

void DeviceWorker::dispatch(const XbusMessage& message)
{
    switch (state_) {
    case SessionState::Initialising: handleInitMessage(message); break;
    case SessionState::Streaming: handleStreamMessage(message); break;
    case SessionState::Stopping:
        if (message.mid == XbusMid::GoToConfigAck)
            finishStop();
        break;
    case SessionState::Idle: break;
    }
}

void DeviceWorker::handleInitMessage(const XbusMessage& message)
{
    if (message.mid == XbusMid::WakeUp) {
        // §4.1: a device that just powered up waits 500 ms for this, then starts measuring.
        port_->write(frameBytes(wakeUpAckMessage()));
        emit progress(tr("the device woke up; acknowledged"));
        if (requestIndex_ == 0)
            resendNow();
        return;
    }
    if (message.mid == requests_.at(requestIndex_).replyMid) {
        completeStep(message);
    } else if (message.mid == XbusMid::Error) {
        failInit(tr("the device refused %1: %2").arg(requestName(), qs(xbusErrorText(message.payload))));
    }
    // Anything else (data still streaming before GoToConfigAck, a Configuration after power-up,
    // a late duplicate acknowledgement) is skipped, as the reference drivers do.
}

void DeviceWorker::completeStep(const XbusMessage& reply)
{
    replyTimer_.stop();
    if (const QString problem = applyReply(reply); !problem.isEmpty()) {
        failInit(problem);
        return;
    }
    if (++requestIndex_ == requests_.size()) {
        enterStreaming();
        return;
    }
    tries_ = 0;
    sendRequest();
}

/// Stores what a reply says; a malformed reply is a failure in words.
QString DeviceWorker::applyReply(const XbusMessage& reply)
{
    switch (reply.mid) {
    case XbusMid::GoToConfigAck: info_.baud = currentBaud(); break;
    case XbusMid::DeviceId: {
        const auto parsed = parseDeviceId(reply.payload);
        if (!parsed.ok())
            return tr("the device's answer to ReqDID is malformed: %1").arg(qs(parsed.error));
        info_.deviceId = parsed.value;
        break;
    }
    case XbusMid::ProductCode: {
        const auto parsed = parseProductCode(reply.payload);
        if (!parsed.ok())
            return tr("the device's answer to ReqProductCode is malformed: %1").arg(qs(parsed.error));
        info_.productCode = qs(parsed.value);
        break;
    }
    case XbusMid::FirmwareRev: {
        const auto parsed = parseFirmwareRevision(reply.payload);
        if (!parsed.ok())
            return tr("the device's answer to ReqFWRev is malformed: %1").arg(qs(parsed.error));
        info_.firmware = parsed.value;
        break;
    }
    case XbusMid::OutputConfiguration: return applyOutputConfiguration(reply);
    default: break;
    }
    return {};
}

QString DeviceWorker::applyOutputConfiguration(const XbusMessage& reply)
{
    const auto parsed = parseOutputConfiguration(reply.payload);
    if (!parsed.ok())
        return tr("the device's answer to SetOutputConfiguration is malformed: %1").arg(qs(parsed.error));
    info_.appliedOutput = parsed.value;
    const auto acc = findOutputEntry(parsed.value, MtData2Id::Acceleration);
    const auto gyr = findOutputEntry(parsed.value, MtData2Id::RateOfTurn);
    if (!acc || !gyr)
        return tr("the device does not output both acceleration and rate of turn, which Footpath needs; it "
                  "applied: %1")
            .arg(qs(describeOutputConfiguration(parsed.value)));
    info_.rate_hz = acc->rate_hz;
    assembler_ = SampleAssembler(info_.rate_hz);  // times samples by counter if SampleTimeFine is missing
    warnAboutOutputDifferences();
    emit deviceIdentified(info_);
    return {};
}

void DeviceWorker::warnAboutOutputDifferences()
{
    for (const OutputConfigEntry& wanted : info_.requestedOutput) {
        const auto applied = findOutputEntry(info_.appliedOutput, wanted.dataId);
        const QString name = qs(describeOutputConfiguration({wanted})).section(QLatin1Char(' '), 0, 0);
        if (!applied)
            emit warning(tr("the device does not output %1 (it may lack that sensor)").arg(name));
        else if (applied->rate_hz != wanted.rate_hz)
            emit warning(tr("the device outputs %1 at %2 Hz instead of %3 Hz")
                             .arg(name)
                             .arg(applied->rate_hz)
                             .arg(wanted.rate_hz));
    }
}

void DeviceWorker::failInit(const QString& message)
{
    endSession(SessionEnd::Failed, message);
}

// ---- streaming --------------------------------------------------------------------------

void DeviceWorker::enterStreaming()
{
    // Everything up to the end of GoToMeasurementAck was init traffic; the recording starts
    // with the first byte after it.
    flushRaw(decoder_.pendingOffset());
    if (recorder_.isOpen() && recordingHeaderDue_ && !recorder_.writeHeader(info_))
        recordingFailed(recorder_.error());
    recordingHeaderDue_ = false;
    setState(SessionState::Streaming);
    syncTimer_.start();
}

void DeviceWorker::handleStreamMessage(const XbusMessage& message)
{
    switch (message.mid) {
    case XbusMid::MtData2: handleDataMessage(message); break;
    case XbusMid::Error:
        ++counters_.deviceErrors;
        warnAtMostOncePerSecond(
            tr("the device reported during measurement: %1").arg(qs(xbusErrorText(message.payload))));
        break;
    case XbusMid::WakeUp:
        warnAtMostOncePerSecond(
            tr("the device restarted during measurement (WakeUp); it resumes with its stored settings"));
        break;
    default: break;
    }
}

/// A sick device may send an Error with every sample: each distinct warning goes out at most once
/// a second, so that the signals queued for a busy GUI stay bounded (deviceErrors counts all).
void DeviceWorker::warnAtMostOncePerSecond(const QString& text)
{
    if (!warningClock_.isValid())
        warningClock_.start();
    const qint64 now_ms = warningClock_.elapsed();
    const auto last = lastWarningAt_ms_.constFind(text);
    if (last != lastWarningAt_ms_.constEnd() && now_ms - *last < kRepeatedWarningInterval_ms)
        return;
    lastWarningAt_ms_.insert(text, now_ms);
    emit warning(text);
}

void DeviceWorker::handleDataMessage(const XbusMessage& message)
{
    const MtData2Decoded decoded = decodeMtData2(message.payload);
    if (!decoded.ok()) {
        ++counters_.malformedMessages;
        return;
    }
    const SampleAssembler beforeThisMessage = assembler_;
    const std::optional<LiveSample> sample = assembler_.add(decoded.sample);
    if (sample && settings_.stopAfter_s > 0.0 && sample->imu.time_s >= settings_.stopAfter_s - 1e-9) {
        assembler_ = beforeThisMessage;  // this message is past the end: it counts for nothing
        cutAndStop(decoder_.lastFrameOffset());
        return;
    }
    recordBatch_.push_back(decoded.sample);
    if (sample)
        batch_.push_back(*sample);
}

void DeviceWorker::deliverBatch()
{
    if (recorder_.isOpen() && !recordBatch_.empty() && !recorder_.writeData(recordBatch_))
        recordingFailed(recorder_.error());
    recordBatch_.clear();
    if (batch_.empty())
        return;
    counters_.deviceTime_s = batch_.back().imu.time_s;
    if (queue_.push(batch_))
        emit samplesQueued();
    batch_.clear();
}

/// Where the recordable bytes end: after the last whole message. What follows it (junk, a damaged
/// message, the start of the next one) waits for the next whole message, so that a recording that
/// is stopped, cut short by a full disk or killed ends on a whole message and re-opens without a
/// truncated tail. Garbage longer than any frame is written anyway: nothing is held without bound.
std::uint64_t DeviceWorker::recordableEnd() const
{
    const std::uint64_t decided = decoder_.pendingOffset();
    return decided - lastMessageEnd_ > kXbusMaxFrameSize ? decided : lastMessageEnd_;
}

/// Hands the received bytes before `upToOffset` (whole frames and skipped junk) to the recorder.
void DeviceWorker::flushRaw(std::uint64_t upToOffset)
{
    if (upToOffset <= rawPendingOffset_)
        return;
    const auto count = static_cast<int>(std::min<std::uint64_t>(upToOffset - rawPendingOffset_,
                                                                static_cast<std::uint64_t>(rawPending_.size())));
    if (count <= 0)
        return;
    if (state_ == SessionState::Streaming && recorder_.isOpen() && !recorder_.writeRaw(rawPending_.left(count)))
        recordingFailed(recorder_.error());
    rawPending_.remove(0, count);
    rawPendingOffset_ += static_cast<std::uint64_t>(count);
}

// ---- recording --------------------------------------------------------------------------

void DeviceWorker::startRecording(const RecordingPaths& paths)
{
    if (recorder_.isOpen())
        closeRecording();
    if (!recorder_.open(paths)) {
        emit recordingStopped(paths, recorder_.error());
        return;
    }
    // The header describes the device: before streaming it is written once the device is known.
    recordingHeaderDue_ = state_ != SessionState::Streaming;
    if (!recordingHeaderDue_ && !recorder_.writeHeader(info_)) {
        recordingFailed(recorder_.error());
        return;
    }
    emit recordingStarted(paths);
}

void DeviceWorker::stopRecording()
{
    if (!recorder_.isOpen())
        return;
    deliverBatch();
    closeRecording();
}

void DeviceWorker::closeRecording()
{
    const RecordingPaths paths = recorder_.paths();
    recorder_.close();
    emit recordingStopped(paths, QString());
}

void DeviceWorker::recordingFailed(const QString& error)
{
    // The Recorder has closed its files, keeping what was written; the session goes on.
    emit recordingStopped(recorder_.paths(), error);
}

// ---- ending -----------------------------------------------------------------------------

void DeviceWorker::stop()
{
    switch (state_) {
    case SessionState::Idle:
    case SessionState::Stopping: return;
    case SessionState::Initialising:
        endSession(SessionEnd::Stopped, tr("stopped before the device was ready"));
        return;
    case SessionState::Streaming: cutAndStop(recordableEnd()); return;
    }
}

/// Ends the recording at a frame boundary and asks the device to stop streaming.
void DeviceWorker::cutAndStop(std::uint64_t cutOffset)
{
    updateCounters();
    deliverBatch();
    flushRaw(cutOffset);
    if (recorder_.isOpen())
        closeRecording();
    syncTimer_.stop();
    setState(SessionState::Stopping);
    if (port_ && port_->write(frameBytes(goToConfigMessage())))
        replyTimer_.start(settings_.timeouts.stop_ms);
    else
        finishStop();
}

void DeviceWorker::finishStop()
{
    endSession(SessionEnd::Stopped, summary());
}

void DeviceWorker::onPortFailed(DevicePort::Failure kind, const QString& message)
{
    if (state_ == SessionState::Stopping) {
        finishStop();
        return;
    }
    if (state_ != SessionState::Streaming) {
        failInit(tr("%1 failed during initialisation: %2").arg(settings_.portName, message));
        return;
    }
    // Keep everything received: what the port still holds, the last complete frames, then the
    // bytes of the unfinished one.
    onReadyRead();
    if (state_ != SessionState::Streaming)
        return;
    decoder_.finish();
    XbusMessage frame;
    while (state_ == SessionState::Streaming && decoder_.next(frame))
        dispatch(frame);
    if (state_ != SessionState::Streaming)
        return;  // the last frames reached the requested duration: that stop has ended the session
    deliverBatch();
    flushRaw(rawPendingOffset_ + static_cast<std::uint64_t>(rawPending_.size()));
    updateCounters();
    const QString what = kind == DevicePort::Failure::Vanished
                             ? tr("the port %1 vanished (device unplugged?)").arg(settings_.portName)
                             : tr("reading %1 failed (%2)").arg(settings_.portName, message);
    endSession(SessionEnd::Vanished, tr("%1 after %2 s of measurement; everything received was kept: %3")
                                         .arg(what)
                                         .arg(counters_.deviceTime_s, 0, 'f', 1)
                                         .arg(summary()));
}

void DeviceWorker::endSession(SessionEnd how, const QString& message)
{
    replyTimer_.stop();
    syncTimer_.stop();
    countersTimer_.stop();
    if (recorder_.isOpen() && state_ != SessionState::Streaming) {
        recorder_.discard();  // the device never streamed: leave no empty files behind
        emit recordingStopped(recorder_.paths(), tr("nothing was recorded: %1").arg(message));
    } else if (recorder_.isOpen()) {
        closeRecording();
    }
    releasePort();
    updateCounters();
    countersDirty_ = true;  // the final counters always reach the facade before ended()
    emitCounters();
    setState(SessionState::Idle);
    emit ended(how, message);
}

/// Deferred: a session often ends inside one of the port's own signals.
void DeviceWorker::releasePort()
{
    if (!port_)
        return;
    port_->disconnect(this);
    port_->close();
    port_.release()->deleteLater();
}

void DeviceWorker::shutdown()
{
    if (state_ == SessionState::Streaming) {
        deliverBatch();
        flushRaw(recordableEnd());
    }
    if (state_ != SessionState::Idle)
        endSession(SessionEnd::Stopped, tr("the session was closed"));
    else if (recorder_.isOpen())
        closeRecording();
}

QString DeviceWorker::summary() const
{
    return tr("%1 samples, %2 lost packets, %3 checksum errors, %4 resyncs")
        .arg(counters_.samplesReceived)
        .arg(counters_.packetsLost)
        .arg(counters_.checksumErrors)
        .arg(counters_.resyncs);
}

// ---- counters and state -------------------------------------------------------------------

void DeviceWorker::updateCounters()
{
    // Frozen once a stop cut the stream: what arrives after the cut belongs to no recording.
    if (state_ != SessionState::Initialising && state_ != SessionState::Streaming)
        return;
    const XbusDecodeStats& stats = decoder_.stats();
    counters_.framesDecoded = stats.framesDecoded;
    counters_.checksumErrors = stats.damagedFrames;
    counters_.resyncs = stats.skippedRuns;
    counters_.bytesSkipped = stats.bytesSkipped;
    counters_.junkBytes = stats.bytesSkipped - stats.damagedFrameBytes;
    counters_.samplesReceived = assembler_.samples();
    counters_.packetsLost = assembler_.packetsLost();
    counters_.incompleteMessages = assembler_.incompleteMessages();
    counters_.counterRestarts = assembler_.counterRestarts();
    counters_.samplesNotShown = queue_.dropped();
    countersDirty_ = true;
}

void DeviceWorker::emitCounters()
{
    if (!countersDirty_)
        return;
    countersDirty_ = false;
    emit countersChanged(counters_);
}

void DeviceWorker::setState(SessionState state)
{
    if (state_ == state)
        return;
    state_ = state;
    emit stateChanged(state);
}

}  // namespace footpath
