#pragma once

#include "DeviceTypes.h"

#include <QMutex>

#include <deque>
#include <vector>

namespace footpath {

/// The bounded hand-over from the worker thread to the GUI: the worker pushes batches, the GUI
/// takes everything queued when told. If the GUI falls behind by more than the capacity, the
/// oldest samples are dropped and counted; the recorder is fed in the worker thread and never
/// depends on this queue.
class LiveSampleQueue {
public:
    explicit LiveSampleQueue(std::size_t capacity) : capacity_(capacity == 0 ? 1 : capacity) {}

    /// True if the queue was empty before: only then does the consumer need a new notification.
    bool push(const std::vector<LiveSample>& samples);
    std::vector<LiveSample> takeAll();
    std::uint64_t dropped() const;
    /// Empties the queue and sets its bound for a new session.
    void reset(std::size_t capacity);

private:
    mutable QMutex mutex_;
    std::size_t capacity_;
    std::deque<LiveSample> samples_;
    std::uint64_t dropped_ = 0;
};

}  // namespace footpath
