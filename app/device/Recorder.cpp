#include "Recorder.h"

#include "xbus/XbusControl.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <unistd.h>

namespace footpath {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("Recorder", text);
}

/// The shortest text that reads back as the same double: CSV and .mtb re-import bit-identical.
void appendNumber(QByteArray& out, double value)
{
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    out.append(text, static_cast<int>(result.ptr - text));
}

void appendVector(QByteArray& out, const Eigen::Vector3d& v)
{
    for (int axis = 0; axis < 3; ++axis) {
        out.append(',');
        appendNumber(out, v[axis]);
    }
}

QByteArray configurationFrame(const DeviceInfo& device)
{
    XbusConfiguration configuration = mtData2Configuration(device.deviceId, device.rate_hz, device.firmware);
    const QDateTime now = QDateTime::currentDateTime();  // loggers stamp the file's creation
    configuration.date = now.toString(QStringLiteral("yyyyMMdd")).toStdString();
    configuration.time = now.toString(QStringLiteral("hhmmss")).toStdString() + "00";
    const std::vector<std::uint8_t> frame =
        encodeFrame(xbusMessage(XbusMid::Configuration, encodeConfiguration(configuration)));
    return QByteArray(reinterpret_cast<const char*>(frame.data()), static_cast<int>(frame.size()));
}

}  // namespace

bool Recorder::open(const RecordingPaths& paths)
{
    close();
    paths_ = paths;
    error_.clear();
    headerWritten_ = false;
    rawBytes_ = rows_ = 0;
    if (!openFile(mtb_, paths.mtb) || (!paths.csv.isEmpty() && !openFile(csv_, paths.csv))) {
        close();
        return false;
    }
    return true;
}

bool Recorder::writeHeader(const DeviceInfo& device)
{
    assembler_ = SampleAssembler(device.rate_hz > 0 ? device.rate_hz : 100.0);
    return isOpen() && writeAll(mtb_, configurationFrame(device));
}

void Recorder::discard()
{
    close();
    for (const QString& path : {paths_.mtb, paths_.csv})
        if (!path.isEmpty())
            QFile::remove(path);
}

bool Recorder::openFile(QFile& file, const QString& path)
{
    const QFileInfo folder(QFileInfo(path).absolutePath());
    if (!folder.isDir()) {
        error_ = tr("cannot record to %1: the folder %2 does not exist").arg(path, folder.filePath());
        return false;
    }
    file.setFileName(path);
    // Unbuffered: each write is a system call, so the data is safe from a crash of this program
    // and a full disk is noticed by the write that hits it, not at the end.
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Unbuffered)) {
        error_ = tr("cannot record to %1: %2 (is the folder %3 writable?)")
                     .arg(path, file.errorString(), QDir::toNativeSeparators(folder.filePath()));
        return false;
    }
    return true;
}

bool Recorder::writeRaw(const QByteArray& bytes)
{
    if (!mtb_.isOpen() || bytes.isEmpty())
        return mtb_.isOpen();
    if (!writeAll(mtb_, bytes))
        return false;
    rawBytes_ += static_cast<std::uint64_t>(bytes.size());
    return true;
}

bool Recorder::writeData(const std::vector<MtData2Sample>& messages)
{
    if (!isOpen())
        return false;
    QByteArray text;
    const std::uint64_t rowsBefore = assembler_.samples();
    appendRows(text, messages);
    if (csv_.isOpen() && !text.isEmpty() && !writeAll(csv_, text))
        return false;
    rows_ += assembler_.samples() - rowsBefore;
    return true;
}

void Recorder::appendRows(QByteArray& out, const std::vector<MtData2Sample>& messages)
{
    for (const MtData2Sample& message : messages) {
        const std::optional<LiveSample> sample = assembler_.add(message);
        if (!sample)
            continue;
        if (!headerWritten_) {
            format_ = LiveCsvFormat::following(*sample);
            out += format_.header();
            headerWritten_ = true;
        }
        format_.appendRow(out, *sample);
    }
}

LiveCsvFormat LiveCsvFormat::following(const LiveSample& first)
{
    return {first.imu.hasMag(), first.imu.hasPressure()};
}

QByteArray LiveCsvFormat::header() const
{
    QByteArray header = "time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z";
    if (withMag)
        header += ",mag_x,mag_y,mag_z";
    if (withPressure)
        header += ",pressure_pa";
    return header + ",packet_counter\n";
}

void LiveCsvFormat::appendRow(QByteArray& out, const LiveSample& sample) const
{
    appendNumber(out, sample.imu.time_s);
    appendVector(out, sample.imu.acc_mps2);
    appendVector(out, sample.imu.gyr_radps);
    if (withMag)
        appendVector(out, sample.imu.mag);
    if (withPressure) {
        out.append(',');
        appendNumber(out, sample.imu.pressure_pa);
    }
    out.append(',');
    if (sample.packetCounter)  // readers take time from time_s; an empty counter cell is ignored
        out.append(QByteArray::number(*sample.packetCounter));
    out.append('\n');
}

QString writeSamplesCsv(const QString& path, const std::vector<LiveSample>& samples)
{
    if (samples.empty())
        return tr("%1: there are no samples to save").arg(QDir::toNativeSeparators(path));
    const LiveCsvFormat format = LiveCsvFormat::following(samples.front());
    QByteArray text = format.header();
    for (const LiveSample& sample : samples)
        format.appendRow(text, sample);
    QSaveFile file(path);  // all or nothing: a failed save leaves no truncated file
    if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size() || !file.commit())
        return tr("cannot save %1: %2").arg(QDir::toNativeSeparators(path), file.errorString());
    return {};
}

bool Recorder::writeAll(QFile& file, const QByteArray& bytes)
{
    const qint64 before = file.pos();
    if (file.write(bytes) != bytes.size()) {
        const QString reason = file.errorString();
        // A write cut short leaves half a frame or half a row: cut it off, so that the file ends
        // on the last whole write and re-opens cleanly (shrinking works on a full disk, too).
        file.resize(before);
        return fail(file, tr("writing failed"), reason);
    }
    dirty_ = true;
    return true;
}

bool Recorder::sync()
{
    if (!dirty_)
        return isOpen();
    for (QFile* file : {&mtb_, &csv_}) {
        if (file->isOpen() && ::fsync(file->handle()) != 0)
            return fail(*file, tr("flushing to the disk failed"), QString::fromLocal8Bit(std::strerror(errno)));
    }
    dirty_ = false;
    return true;
}

bool Recorder::fail(QFile& file, const QString& what, const QString& reason)
{
    error_ = tr("%1 for %2: %3 (disk full, file size limit reached, or the disk removed?); the recording "
                "stopped at %4 bytes, everything before was kept")
                 .arg(what, QDir::toNativeSeparators(file.fileName()), reason)
                 .arg(file.size());
    close();
    return false;
}

void Recorder::close()
{
    if (dirty_) {
        dirty_ = false;  // one attempt: a failing disk must not make close() loop
        for (QFile* file : {&mtb_, &csv_})
            if (file->isOpen())
                ::fsync(file->handle());
    }
    mtb_.close();
    csv_.close();
}

}  // namespace footpath
