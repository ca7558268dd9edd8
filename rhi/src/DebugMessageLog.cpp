#include "penumbra/rhi/DebugMessageLog.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace penumbra::rhi {

void DebugMessageLog::record(std::string message)
{
    std::lock_guard lock(mutex_);
    messages_.push_back(std::move(message));
}

std::vector<std::string> DebugMessageLog::all() const
{
    std::lock_guard lock(mutex_);
    return messages_;
}

void DebugMessageLog::clear()
{
    std::lock_guard lock(mutex_);
    messages_.clear();
    reported_ = 0;
}

void DebugMessageLog::openGroup(std::string name)
{
    std::lock_guard lock(mutex_);
    groups_.push_back(std::move(name));
}

void DebugMessageLog::closeGroup()
{
    std::lock_guard lock(mutex_);
    if (!groups_.empty())
        groups_.pop_back();
}

std::string DebugMessageLog::openGroups() const
{
    std::lock_guard lock(mutex_);
    return groups_.empty() ? std::string() : fmt::format(" [labels: {}]", fmt::join(groups_, " > "));
}

void DebugMessageLog::raiseUnreported(std::string_view source)
{
    std::lock_guard lock(mutex_);
    if (reported_ == messages_.size())
        return;
    const std::vector<std::string> fresh(messages_.begin() + std::ptrdiff_t(reported_), messages_.end());
    reported_ = messages_.size();
    throw Error(fmt::format("{} reported {} message(s):\n{}", source, fresh.size(), fmt::join(fresh, "\n")));
}

} // namespace penumbra::rhi
