#pragma once

#include "DeviceTypes.h"
#include "SampleAssembler.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QFile>
#include <QString>

#include <vector>

namespace footpath {

/// The canonical CSV of live samples: time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z[,mag_x,mag_y,mag_z]
/// [,pressure_pa],packet_counter, the optional columns as the first sample has them. Numbers are
/// the shortest text that reads back as the same double.
struct LiveCsvFormat {
    bool withMag = false;
    bool withPressure = false;
    static LiveCsvFormat following(const LiveSample& first);
    QByteArray header() const;
    void appendRow(QByteArray& out, const LiveSample& sample) const;
};

/// Saves samples kept in memory (a session that was not recorded) as that CSV, which the workspace
/// opens as a recording. Returns an error naming the file, or empty.
QString writeSamplesCsv(const QString& path, const std::vector<LiveSample>& samples);

/// Writes a live session to disk as it arrives: the raw bytes to an .mtb file (after a
/// Configuration message describing the device, as Xsens loggers do, so that importers recognise
/// it; MT Manager also wants the calibration blob it does not hold, docs/xbus.md §7.1) and the
/// decoded samples to a CSV with the canonical columns
/// time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z[,mag_x,mag_y,mag_z][,pressure_pa],packet_counter.
///
/// Files are unbuffered, so every write reaches the operating system at once (a crash of the
/// program loses nothing) and a full disk fails the write that hits it, which is then cut off so
/// that both files end on a whole message and row; sync() forces the data onto the disk (the
/// worker calls it every second, so a power loss costs at most that).
/// Not thread-safe: it lives in the session's worker thread.
class Recorder {
public:
    Recorder() = default;
    ~Recorder() { close(); }
    Recorder(const Recorder&) = delete;
    Recorder& operator=(const Recorder&) = delete;

    /// Creates the files; false, with error() in words, if a folder is missing or not writable.
    /// Called before the device is known, so that a bad path is reported before any waiting.
    bool open(const RecordingPaths& paths);
    /// Starts the .mtb with the device's Configuration message; once, before any data.
    bool writeHeader(const DeviceInfo& device);
    bool writeRaw(const QByteArray& bytes);
    /// Decoded data messages in arrival order; the CSV gets a row for each intact one, timed
    /// from the first recorded message exactly as importing the .mtb will time it. The columns
    /// follow the first row: mag and pressure only if it has them.
    bool writeData(const std::vector<MtData2Sample>& messages);
    /// Closes the files and deletes them: for a session that failed before any data came.
    void discard();
    /// Flushes to the disk (fsync) if anything was written since the last time.
    bool sync();
    void close();

    bool isOpen() const { return mtb_.isOpen(); }
    const RecordingPaths& paths() const { return paths_; }
    QString error() const { return error_; }
    std::uint64_t rawBytesWritten() const { return rawBytes_; }
    std::uint64_t rowsWritten() const { return rows_; }
    std::uint64_t packetsLost() const { return assembler_.packetsLost(); }

private:
    bool openFile(QFile& file, const QString& path);
    bool writeAll(QFile& file, const QByteArray& bytes);
    bool fail(QFile& file, const QString& what, const QString& reason);
    void appendRows(QByteArray& out, const std::vector<MtData2Sample>& messages);

    RecordingPaths paths_;
    QFile mtb_;
    QFile csv_;
    QString error_;
    SampleAssembler assembler_;
    bool headerWritten_ = false;
    LiveCsvFormat format_;
    bool dirty_ = false;
    std::uint64_t rawBytes_ = 0;
    std::uint64_t rows_ = 0;
};

}  // namespace footpath
