#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

namespace footpath {

/// A second thread that runs the jobs handed to it one at a time, in order: for a pass whose
/// sequential part (a recursion) can hand finished stretches to a second core for the part that is
/// independent per sample (RtsSmoother's backward pass). The destructor waits for the jobs handed
/// over and joins the thread.
class SerialWorker {
public:
    SerialWorker()
        : thread_([this] { run(); })
    {
    }
    ~SerialWorker()
    {
        waitUntilAtMost(0);
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            stopping_ = true;
        }
        changed_.notify_all();
        thread_.join();
    }
    SerialWorker(const SerialWorker&) = delete;
    SerialWorker& operator=(const SerialWorker&) = delete;

    void post(std::function<void()> job)
    {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            jobs_.push_back(std::move(job));
        }
        changed_.notify_all();
    }

    /// Blocks until at most this many jobs are queued or running.
    void waitUntilAtMost(std::size_t pending)
    {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [&] { return jobs_.size() <= pending; });
    }

private:
    void run()
    {
        for (;;) {
            std::function<void()>* job = nullptr;
            {
                std::unique_lock<std::mutex> lock(mutex_);
                changed_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
                if (jobs_.empty())
                    return;
                // It stays queued while it runs, so waitUntilAtMost counts it; post() appends at
                // the back, which leaves a reference to the front valid.
                job = &jobs_.front();
            }
            (*job)();
            {
                const std::lock_guard<std::mutex> lock(mutex_);
                jobs_.pop_front();
            }
            changed_.notify_all();
        }
    }

    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::function<void()>> jobs_;
    bool stopping_ = false;
    std::thread thread_;  ///< last: starts after the members it reads exist
};

}  // namespace footpath
