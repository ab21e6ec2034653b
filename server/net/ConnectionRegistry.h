#pragma once
// The open WebSocket connections, so shutdown can send each a close frame and end those that did not close.
#include <atomic>
#include <cstddef>
#include <memory>
#include <mutex>
#include <map>
#include <string>
#include <vector>

#include "net/Connection.h"

namespace specula::net {

class WebSocketConnection;

class ConnectionRegistry {
 public:
  void add(const std::shared_ptr<WebSocketConnection>& connection);
  void remove(const WebSocketConnection* connection);
  std::size_t size() const;
  // Asks every open connection to close with `code`; returns how many were asked.
  std::size_t closeAll(CloseCode code, const std::string& reason);
  // Ends every connection still open at once; only once no thread runs the connections' handlers.
  // Returns how many there were.
  std::size_t abandonAll();

  // Counts open TCP connections (HTTP or WebSocket): hold the token while the connection lives.
  std::shared_ptr<void> openConnection();
  std::size_t openConnections() const { return openConnections_.load(); }

 private:
  std::vector<std::shared_ptr<WebSocketConnection>> open() const;

  mutable std::mutex mutex_;
  std::shared_ptr<std::atomic<std::size_t>> openConnectionsShared_ = std::make_shared<std::atomic<std::size_t>>(0);
  std::atomic<std::size_t>& openConnections_ = *openConnectionsShared_;
  std::map<const WebSocketConnection*, std::weak_ptr<WebSocketConnection>> connections_;
};

}  // namespace specula::net
