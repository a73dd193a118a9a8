// A background thread that runs the latest job asked for (the Front tab's engine and motion-truth
// workers): a new job cancels the running one and its results are dropped; the state changes only
// while its job is still the one asked for, each change bumping State::version; the destructor
// cancels and joins. Job and State each have a std::string `key`; State has an unsigned `version`.
#pragma once
#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace ssao {

template <class Job, class State>
class LatestJob {
  public:
    // `work` runs each job on the thread; `wake` (may be empty) is called after each change.
    LatestJob(std::function<void(const Job&)> work, std::function<void()> wake)
        : work_(std::move(work)), wake_(std::move(wake)), thread_([this] { run(); }) {}
    ~LatestJob() {
        {
            std::lock_guard<std::mutex> lock(m_);
            quit_ = true;
            pending_.reset();
        }
        cancel_ = true;
        cv_.notify_all();
        thread_.join();
    }
    LatestJob(const LatestJob&) = delete;
    LatestJob& operator=(const LatestJob&) = delete;

    // Starts `job` unless it has the key of the one started last; the state starts as `fresh`.
    void start(Job job, State fresh = {}) {
        std::lock_guard<std::mutex> lock(m_);
        if (job.key == state_.key) return;
        cancel_ = true; // the running job, if any, stops at its next check
        fresh.key = job.key;
        state_ = std::move(fresh);
        state_.version = ++version_;
        pending_ = std::move(job);
        cv_.notify_all();
    }
    // Forgets the job: the running one stops at its next check, its results are dropped.
    void cancel() {
        std::lock_guard<std::mutex> lock(m_);
        cancel_ = true;
        pending_.reset();
        state_ = State{};
        state_.version = ++version_;
    }
    State state() const {
        std::lock_guard<std::mutex> lock(m_);
        return state_;
    }
    // Changes the state while `job` is still the one asked for; false once it was cancelled or replaced.
    bool publish(const Job& job, const std::function<void(State&)>& change) {
        {
            std::lock_guard<std::mutex> lock(m_);
            if (state_.key != job.key || cancel_) return false;
            change(state_);
            state_.version = ++version_;
        }
        if (wake_) wake_();
        return true;
    }
    // The state's version alone (cheap to poll every frame).
    unsigned version() const {
        std::lock_guard<std::mutex> lock(m_);
        return state_.version;
    }
    // True while the thread works on a job (a cancelled one included, until its work returns).
    bool running() const { return running_.load(); }
    // Set when the running job should stop (for work that polls an atomic flag).
    const std::atomic<bool>& cancelled() const { return cancel_; }

  private:
    void run() {
        for (;;) {
            Job job;
            {
                std::unique_lock<std::mutex> lock(m_);
                cv_.wait(lock, [&] { return quit_ || pending_.has_value(); });
                if (quit_) return;
                job = std::move(*pending_);
                pending_.reset();
                cancel_ = false;
                running_ = true;
            }
            work_(job);
            running_ = false;
        }
    }

    std::function<void(const Job&)> work_;
    std::function<void()> wake_;
    mutable std::mutex m_;
    std::condition_variable cv_;
    std::optional<Job> pending_;
    State state_;
    unsigned version_ = 0;
    bool quit_ = false;
    std::atomic<bool> cancel_{false}, running_{false};
    std::thread thread_; // last: started once everything above exists
};

} // namespace ssao
