#include "exec/task_sharing.h"

#include <algorithm>

namespace veridem::exec
{

TaskSharing::Group* TaskSharing::take(std::size_t& index)
{
    if (open_.empty())
        return nullptr;
    Group* group = open_.front();
    index = group->next++;
    if (group->next == group->count)
        open_.pop_front();
    return group;
}

void TaskSharing::run(Group& group, std::size_t index)
{
    std::exception_ptr error;
    try
    {
        (*group.task)(index);
    }
    catch (...)
    {
        error = std::current_exception();
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    if (error && (!group.error || index < group.errorIndex))
    {
        group.error = error;
        group.errorIndex = index;
    }
    ++group.finished;
    changed_.notify_all();
}

void TaskSharing::forEach(std::size_t count, const std::function<void(std::size_t)>& task)
{
    if (count == 0)
        return;
    Group group;
    group.task = &task;
    group.count = count;
    std::unique_lock<std::mutex> lock(mutex_);
    open_.push_back(&group);
    changed_.notify_all();
    bool idleDone = false; // the idle work said it had nothing left
    while (group.finished < group.count)
    {
        // Own tasks first (this thread's caller waits for them), then anyone's.
        std::size_t index = 0;
        Group* chosen = nullptr;
        if (group.next < group.count)
        {
            chosen = &group;
            index = group.next++;
            if (group.next == group.count)
                open_.erase(std::find(open_.begin(), open_.end(), &group));
        }
        else
            chosen = take(index);
        if (chosen)
        {
            lock.unlock();
            run(*chosen, index);
            lock.lock();
        }
        else if (idle_ && !idleDone)
        {
            lock.unlock();
            idleDone = !idle_();
            lock.lock();
        }
        else
            changed_.wait(lock, [&] { return group.finished == group.count || !open_.empty(); });
    }
    if (group.error)
        std::rethrow_exception(group.error);
}

bool TaskSharing::runPending()
{
    std::unique_lock<std::mutex> lock(mutex_);
    std::size_t index = 0;
    Group* group = take(index);
    if (!group)
        return false;
    lock.unlock();
    run(*group, index);
    return true;
}

bool TaskSharing::waitForTask()
{
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return closed_ || !open_.empty(); });
    return !open_.empty();
}

void TaskSharing::close()
{
    const std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
    changed_.notify_all();
}

} // namespace veridem::exec
