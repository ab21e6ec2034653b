#include "net/ConnectionRegistry.h"

#include <vector>

namespace specula::net {

void ConnectionRegistry::add(const std::shared_ptr<MessageSink>& sink) {
  std::lock_guard lock(mutex_);
  sinks_[sink.get()] = sink;
}

void ConnectionRegistry::remove(const MessageSink* sink) {
  std::lock_guard lock(mutex_);
  sinks_.erase(sink);
}

std::size_t ConnectionRegistry::size() const {
  std::lock_guard lock(mutex_);
  return sinks_.size();
}

std::size_t ConnectionRegistry::closeAll(CloseCode code, const std::string& reason) {
  std::vector<std::shared_ptr<MessageSink>> open;
  {
    std::lock_guard lock(mutex_);
    for (const auto& [raw, weak] : sinks_)
      if (auto sink = weak.lock()) open.push_back(std::move(sink));
  }
  for (const auto& sink : open) sink->close(code, reason);  // outside the lock: close may re-enter remove()
  return open.size();
}

std::shared_ptr<void> ConnectionRegistry::openConnection() {
  ++openConnections_;
  // The token shares the counter, so it may outlive the registry during shutdown.
  return std::shared_ptr<void>(nullptr, [counter = openConnectionsShared_](void*) { --*counter; });
}

}  // namespace specula::net
