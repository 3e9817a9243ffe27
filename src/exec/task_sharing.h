// Task sharing between long-lived worker threads: a thread that has independent pieces of work
// (the fills of a silo, the piles of a sweep) offers them with forEach(), runs them itself, and
// idle workers take the ones it has not started. Used by the verification runner, whose workers
// each run one case at a time: a case split into tasks no longer keeps one core busy while the
// other has run out of cases. Coarse grained (each task seconds to minutes): a mutex and condition
// variables, no lock-free queue. Results are the tasks' own (each writes its own slot), so they do
// not depend on which thread ran which task.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <utility>

namespace veridem::exec
{

class TaskSharing
{
  public:
    /// Runs task(i) for every i in [0, count), on the calling thread and on the workers that call
    /// runPending() or waitForTask(); returns when all have returned. Tasks start in index order.
    /// While its own tasks run elsewhere, the calling thread runs other threads' pending tasks,
    /// else the idle work (setIdleWork), else sleeps. If tasks throw, the rest still run and the
    /// first exception (by index) is rethrown here.
    void forEach(std::size_t count, const std::function<void(std::size_t)>& task);

    /// What a thread waiting in forEach() does when no task is pending: `work` returns true if it
    /// did something (the runner: starts and finishes a case not yet started), false if there is
    /// nothing left to do. Thread-safe, called without the lock; set before any forEach().
    void setIdleWork(std::function<bool()> work) { idle_ = std::move(work); }

    /// Runs one pending task of any forEach() if there is one; false if there was none.
    bool runPending();

    /// Blocks until a task is pending (true) or close() has been called (false).
    bool waitForTask();

    /// Wakes the threads in waitForTask() for good (the work is over).
    void close();

  private:
    struct Group
    {
        const std::function<void(std::size_t)>* task = nullptr;
        std::size_t count = 0, next = 0, finished = 0;
        std::exception_ptr error;
        std::size_t errorIndex = 0;
    };
    /// Takes the next index of the first group with one left (lock held); null if none.
    Group* take(std::size_t& index);
    /// Runs task `index` of `group` without the lock and records its end.
    void run(Group& group, std::size_t index);

    std::mutex mutex_;
    std::condition_variable changed_; // a task was offered, a task finished, or close()
    std::deque<Group*> open_;         // groups with tasks not yet started, oldest first
    bool closed_ = false;
    std::function<bool()> idle_;
};

} // namespace veridem::exec
