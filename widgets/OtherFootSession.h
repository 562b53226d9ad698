#pragma once

#include "Recording.h"
#include "Result.h"
#include "gait/BilateralGait.h"
#include "io/Import.h"

#include <Eigen/Core>

#include <QObject>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace footpath {

class AnalysisSession;
class PipelineRunner;
class RecordingLoader;

/// The right foot of a walk opened as a left/right pair; the session holds the left. Reads the
/// right foot's file, estimates it with the session's parameters (again whenever they change) and,
/// once both feet have a result, computes what they give together (double support, symmetry) and
/// the right path in the left path's frame. Time base: the two files' own time stamps, taken as
/// one clock (see core/gait/BilateralGait.h).
class OtherFootSession : public QObject {
    Q_OBJECT
public:
    explicit OtherFootSession(AnalysisSession& session, QObject* parent = nullptr);
    ~OtherFootSession() override;

    /// Reads path as the right foot and estimates it; notes say how the sides were decided.
    void load(const QString& path, const QStringList& notes = {});
    /// Back to one foot.
    void clear();
    bool isActive() const { return !path_.isEmpty(); }
    QString path() const { return path_; }
    QStringList notes() const { return notes_; }
    std::shared_ptr<const Recording> recording() const { return recording_; }
    /// What reading the right foot's file gave (its format, gaps, warnings), null until it is read.
    std::shared_ptr<const ImportResult> read() const { return read_; }
    std::shared_ptr<const Result> result() const { return result_; }
    /// Double support and symmetry (its warnings led by the pairing's notes); nothing until both
    /// feet have a result.
    const std::optional<BilateralGait>& bothFeet() const { return bothFeet_; }
    /// The right foot's path turned and shifted onto the left's; empty until both have a result.
    const std::vector<Eigen::Vector3d>& alignedPath() const { return alignedPath_; }

signals:
    /// The right foot's result, the figures of both or the pairing itself changed.
    void changed();
    /// The right foot's file was read (read() holds it).
    void readDone(const QString& path);
    void failed(const QString& message);

private:
    void estimate();
    void combine();

    AnalysisSession& session_;
    RecordingLoader* loader_;
    PipelineRunner* runner_;
    QString path_;
    QStringList notes_;
    std::shared_ptr<const ImportResult> read_;
    std::shared_ptr<const Recording> recording_;
    std::shared_ptr<const Result> result_;
    /// From run() to the runner's report (finished or failed): PipelineRunner::isRunning() turns
    /// false before its finished signal is handled, when the new result is not here yet.
    bool estimating_ = false;
    std::optional<BilateralGait> bothFeet_;
    std::vector<Eigen::Vector3d> alignedPath_;
};

}  // namespace footpath
