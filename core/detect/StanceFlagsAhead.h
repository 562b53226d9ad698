#pragma once

#include "Recording.h"
#include "Result.h"
#include "nav/Parameters.h"

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace footpath {

/// A recording's stance flags, decided on a second thread while a reader follows behind them: the
/// filter reads a sample's flags only when it reaches that sample, and the detector is about a tenth
/// of a run (the 30-minute walk: 9 of 100 ms), so the two overlap instead of adding up. The
/// detector writes into flags (detectStanceInto); waitFor() says when a prefix may be read.
/// Mode::First (a caller that keeps every core busy already), or when no thread can be started,
/// decides the flags in the constructor. Either way they are the same flags as detectStance's.
class StanceFlagsAhead {
public:
    enum class Mode { Concurrent, First };
    /// samples and flags must outlive this object, which writes flags until every one is decided
    /// (waitForAll) or it is destroyed; params is copied. afterFlags, if given, runs once every
    /// flag is decided, on the detector's thread (work on the samples alone that the reader needs
    /// only at its end, done while it reads) or in the constructor; waitForAfterFlags() waits for it.
    StanceFlagsAhead(const std::vector<ImuSample>& samples, const Parameters& params, StanceFlags& flags, Mode mode,
                     std::function<void()> afterFlags = {});
    /// Stops the detector at its next batch and waits for it (a cancelled run).
    ~StanceFlagsAhead();
    StanceFlagsAhead(const StanceFlagsAhead&) = delete;
    StanceFlagsAhead& operator=(const StanceFlagsAhead&) = delete;

    /// Blocks until the flags of the first count samples are final (count at most the samples').
    /// Rethrows what the detector threw (out of memory).
    void waitFor(std::size_t count)
    {
        if (count > known_)
            waitForSlow(count);
    }
    /// Blocks until every flag is final.
    void waitForAll() { waitFor(samples_); }
    /// Whether every flag is final now (without waiting).
    bool allDecided();
    /// Blocks until afterFlags has run (every flag is final then too). Rethrows what it or the
    /// detector threw.
    void waitForAfterFlags();

private:
    /// The detector's thread: the flags, each decided prefix published, or what it threw.
    void detectOnThisThread(const std::vector<ImuSample>& samples, StanceFlags& flags);
    void waitForSlow(std::size_t count);
    /// Publishes a decided prefix; false once the reader has gone.
    bool publish(std::size_t decided);
    /// On the detector's thread: whether every flag was decided and the reader still wants them.
    bool allDecidedHere();
    /// afterFlags, if any; what it threw.
    std::exception_ptr runAfterFlags() const;
    /// Marks afterFlags as run (or abandoned), with what went wrong if anything did.
    void afterFlagsEnded(std::exception_ptr failure);

    const Parameters params_;
    const std::function<void()> afterFlags_;
    const std::size_t samples_;
    std::size_t known_ = 0;  ///< the reader's copy of decided_, so most waitFor() calls lock nothing
    std::mutex mutex_;
    std::condition_variable published_;
    std::size_t decided_ = 0;  ///< guarded by mutex_, as are the two below
    bool stop_ = false;
    std::exception_ptr failure_;
    bool afterFlagsEnded_ = false;
    std::exception_ptr afterFlagsFailure_;
    std::thread detector_;
};

}  // namespace footpath
