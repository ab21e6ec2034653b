#pragma once
// The open WebSocket connections, so shutdown can send each a close frame.
#include <atomic>
#include <cstddef>
#include <memory>
#include <mutex>
#include <map>

#include "net/Connection.h"

namespace specula::net {

class ConnectionRegistry {
 public:
  void add(const std::shared_ptr<MessageSink>& sink);
  void remove(const MessageSink* sink);
  std::size_t size() const;
  // Asks every open connection to close with `code`; returns how many were asked.
  std::size_t closeAll(CloseCode code, const std::string& reason);

  // Counts open TCP connections (HTTP or WebSocket): hold the token while the connection lives.
  std::shared_ptr<void> openConnection();
  std::size_t openConnections() const { return openConnections_.load(); }

 private:
  mutable std::mutex mutex_;
  std::shared_ptr<std::atomic<std::size_t>> openConnectionsShared_ = std::make_shared<std::atomic<std::size_t>>(0);
  std::atomic<std::size_t>& openConnections_ = *openConnectionsShared_;
  std::map<const MessageSink*, std::weak_ptr<MessageSink>> sinks_;
};

}  // namespace specula::net
