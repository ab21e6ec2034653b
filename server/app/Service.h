#pragma once
// The running streaming service: session hub (render + encode threads) behind the HTTP/WebSocket
// server. Used by `specula serve` and `specula bench serve`.
#include <chrono>
#include <memory>
#include <string>

#include "base/Result.h"
#include "net/HttpServer.h"
#include "scene/Scene.h"
#include "session/SessionHub.h"

namespace specula::app {

struct ServiceConfig {
  std::shared_ptr<const scene::Scene> scene;
  std::string glBackend = "auto";  // --gl; each render thread opens its own context
  session::HubOptions hub;
  net::ServerOptions server;
};

class Service {
 public:
  // Creates the renderers (fails on no GL or shader errors), then binds and listens.
  static Result<std::unique_ptr<Service>> start(ServiceConfig config);
  ~Service();  // stop(kDefaultGrace)

  std::uint16_t port() const { return server_->port(); }
  session::SessionHub& hub() { return *hub_; }

  // Refuses new sessions, closes every client with 1001 within `grace`, then joins every thread.
  void stop(std::chrono::milliseconds grace = std::chrono::milliseconds(900));

 private:
  Service() = default;
  std::unique_ptr<session::SessionHub> hub_;
  std::unique_ptr<net::HttpServer> server_;
};

}  // namespace specula::app
