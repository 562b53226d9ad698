#include "LiveSampleQueue.h"

#include <QMutexLocker>

#include <algorithm>

namespace footpath {

bool LiveSampleQueue::push(const std::vector<LiveSample>& samples)
{
    QMutexLocker lock(&mutex_);
    const bool wasEmpty = samples_.empty();
    // The newest samples stay; the queue never holds more than its capacity, not even for a moment.
    const std::size_t incoming = std::min(samples.size(), capacity_);
    dropped_ += samples.size() - incoming;
    if (samples_.size() + incoming > capacity_) {
        const std::size_t excess = samples_.size() + incoming - capacity_;
        samples_.erase(samples_.begin(), samples_.begin() + static_cast<std::ptrdiff_t>(excess));
        dropped_ += excess;
    }
    samples_.insert(samples_.end(), samples.end() - static_cast<std::ptrdiff_t>(incoming), samples.end());
    return wasEmpty && !samples_.empty();
}

std::vector<LiveSample> LiveSampleQueue::takeAll()
{
    QMutexLocker lock(&mutex_);
    std::vector<LiveSample> out(samples_.begin(), samples_.end());
    samples_.clear();
    return out;
}

std::uint64_t LiveSampleQueue::dropped() const
{
    QMutexLocker lock(&mutex_);
    return dropped_;
}

void LiveSampleQueue::reset(std::size_t capacity)
{
    QMutexLocker lock(&mutex_);
    capacity_ = capacity == 0 ? 1 : capacity;
    samples_.clear();
    dropped_ = 0;
}

}  // namespace footpath
