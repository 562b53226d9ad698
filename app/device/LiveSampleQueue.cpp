#include "LiveSampleQueue.h"

#include <QMutexLocker>

namespace footpath {

bool LiveSampleQueue::push(const std::vector<LiveSample>& samples)
{
    QMutexLocker lock(&mutex_);
    const bool wasEmpty = samples_.empty();
    samples_.insert(samples_.end(), samples.begin(), samples.end());
    if (samples_.size() > capacity_) {
        const std::size_t excess = samples_.size() - capacity_;
        samples_.erase(samples_.begin(), samples_.begin() + static_cast<std::ptrdiff_t>(excess));
        dropped_ += excess;
    }
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
