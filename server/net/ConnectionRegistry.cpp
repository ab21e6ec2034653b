#include "net/ConnectionRegistry.h"

#include <vector>

#include "net/WebSocketConnection.h"

namespace specula::net {

void ConnectionRegistry::add(const std::shared_ptr<WebSocketConnection>& connection) {
  std::lock_guard lock(mutex_);
  connections_[connection.get()] = connection;
}

void ConnectionRegistry::remove(const WebSocketConnection* connection) {
  std::lock_guard lock(mutex_);
  connections_.erase(connection);
}

std::size_t ConnectionRegistry::size() const {
  std::lock_guard lock(mutex_);
  return connections_.size();
}

std::vector<std::shared_ptr<WebSocketConnection>> ConnectionRegistry::open() const {
  std::vector<std::shared_ptr<WebSocketConnection>> open;
  std::lock_guard lock(mutex_);
  for (const auto& [raw, weak] : connections_)
    if (auto connection = weak.lock()) open.push_back(std::move(connection));
  return open;
}

std::size_t ConnectionRegistry::closeAll(CloseCode code, const std::string& reason) {
  const auto connections = open();
  // Outside the lock: closing may re-enter remove().
  for (const auto& connection : connections) connection->close(code, reason);
  return connections.size();
}

std::size_t ConnectionRegistry::abandonAll() {
  const auto connections = open();
  for (const auto& connection : connections) connection->abandon();
  return connections.size();
}

std::shared_ptr<void> ConnectionRegistry::openConnection() {
  ++openConnections_;
  // The token shares the counter, so it may outlive the registry during shutdown.
  return std::shared_ptr<void>(nullptr, [counter = openConnectionsShared_](void*) { --*counter; });
}

}  // namespace specula::net
