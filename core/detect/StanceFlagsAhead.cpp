#include "detect/StanceFlagsAhead.h"

#include "detect/StanceDetector.h"

#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

namespace footpath {

StanceFlagsAhead::StanceFlagsAhead(const std::vector<ImuSample>& samples, const Parameters& params,
                                   StanceFlags& flags, Mode mode, std::function<void()> afterFlags)
    : params_(params)
    , afterFlags_(std::move(afterFlags))
    , samples_(samples.size())
{
    if (mode == Mode::Concurrent) {
        try {
            detector_ = std::thread([this, &samples, &flags] { detectOnThisThread(samples, flags); });
            return;
        } catch (const std::system_error&) {
            // No thread to be had (a process at its limit): decided first, as with Mode::First.
        }
    }
    detectStanceInto(samples, params, flags, {});
    known_ = decided_ = samples_;
    afterFlagsFailure_ = runAfterFlags();  // for waitForAfterFlags, as with a thread
    afterFlagsEnded_ = true;
}

std::exception_ptr StanceFlagsAhead::runAfterFlags() const
{
    if (afterFlags_) {
        try {
            afterFlags_();
        } catch (...) {
            return std::current_exception();
        }
    }
    return nullptr;
}

void StanceFlagsAhead::detectOnThisThread(const std::vector<ImuSample>& samples, StanceFlags& flags)
{
    std::exception_ptr failure;
    try {
        const bool finished =
            detectStanceInto(samples, params_, flags, [this](std::size_t decided) { return publish(decided); });
        const std::lock_guard<std::mutex> lock(mutex_);
        if (finished && decided_ < samples_) {
            // A detector that skipped samples: the reader would wait for them for ever.
            failure = std::make_exception_ptr(std::logic_error(
                "the stance detector decided " + std::to_string(decided_) + " of " + std::to_string(samples_) + " samples"));
        }
    } catch (...) {
        failure = std::current_exception();
    }
    if (failure) {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            failure_ = failure;
            published_.notify_all();
        }
        afterFlagsEnded(failure);
        return;
    }
    afterFlagsEnded(allDecidedHere() ? runAfterFlags() : nullptr);
}

bool StanceFlagsAhead::allDecidedHere()
{
    const std::lock_guard<std::mutex> lock(mutex_);
    return decided_ == samples_ && !stop_;
}

void StanceFlagsAhead::afterFlagsEnded(std::exception_ptr failure)
{
    const std::lock_guard<std::mutex> lock(mutex_);
    afterFlagsEnded_ = true;
    afterFlagsFailure_ = failure;
    published_.notify_all();
}

void StanceFlagsAhead::waitForAfterFlags()
{
    std::unique_lock<std::mutex> lock(mutex_);
    published_.wait(lock, [&] { return afterFlagsEnded_; });
    if (afterFlagsFailure_)
        std::rethrow_exception(afterFlagsFailure_);
}

StanceFlagsAhead::~StanceFlagsAhead()
{
    if (!detector_.joinable())
        return;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    detector_.join();
}

bool StanceFlagsAhead::publish(std::size_t decided)
{
    const std::lock_guard<std::mutex> lock(mutex_);
    decided_ = decided;
    published_.notify_all();
    return !stop_;
}

bool StanceFlagsAhead::allDecided()
{
    if (known_ < samples_) {
        const std::lock_guard<std::mutex> lock(mutex_);
        known_ = decided_;
    }
    return known_ == samples_;
}

void StanceFlagsAhead::waitForSlow(std::size_t count)
{
    std::unique_lock<std::mutex> lock(mutex_);
    published_.wait(lock, [&] { return decided_ >= count || failure_; });
    if (failure_)
        std::rethrow_exception(failure_);
    known_ = decided_;
}

}  // namespace footpath
