#pragma once
// The service's one port: HTTP (static client, /healthz, /metrics) and the WebSocket at /ws.
// Beast stays behind this header: callers see options, a port and shutdown.
#include <chrono>
#include <memory>

#include "base/Result.h"
#include "net/Connection.h"
#include "net/ServerOptions.h"

namespace specula::net {

class HttpServer {
 public:
  // Binds, listens and starts `ioThreads` network threads. Fails with a message naming the address
  // when it cannot bind, and refuses a non-loopback bind without a token.
  static Result<std::unique_ptr<HttpServer>> start(ServerOptions options, ConnectionAcceptor& acceptor,
                                                   int ioThreads = 1);
  ~HttpServer();  // shuts down if still running

  std::uint16_t port() const;
  std::size_t openWebSockets() const;
  std::size_t openConnections() const;

  // Stops accepting, sends every WebSocket client a close frame with `code`, waits until they have
  // gone or `grace` has passed, then stops the network threads. Idempotent.
  void shutdown(std::chrono::milliseconds grace, CloseCode code = CloseCode::GoingAway);

 private:
  struct State;
  explicit HttpServer(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace specula::net
