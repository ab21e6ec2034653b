#include "app/Service.h"

#include "app/GlSetup.h"
#include "gl/GlObject.h"
#include "net/Histogram.h"
#include "session/GlFrameRenderer.h"

namespace specula::app {

Result<std::unique_ptr<Service>> Service::start(ServiceConfig config) {
  std::unique_ptr<Service> service(new Service());
  auto rendererFactory = [backend = config.glBackend,
                          scene = config.scene]() -> Result<std::unique_ptr<session::FrameRenderer>> {
    auto context = openGlContext(backend);
    if (!context) return Error{context.error()};
    return session::GlFrameRenderer::create(std::move(*context), scene);
  };
  config.hub.maxMessageBytes = config.server.maxMessageBytes;
  auto hub = session::SessionHub::start(config.scene, config.hub, rendererFactory);
  if (!hub) return Error{hub.error()};
  service->hub_ = std::move(*hub);
  config.server.metricsText = [hub = service->hub_.get()] {
    std::string text = hub->prometheusText();
    net::appendPrometheusSample(text, "specula_gl_objects", "gauge",
                                "GL buffers, textures, framebuffers, vertex arrays and queries alive, all contexts.",
                                static_cast<double>(gl::glObjectsLive.load(std::memory_order_relaxed)));
    return text;
  };
  config.server.notReady = [hub = service->hub_.get()] { return hub->notReady(); };
  auto server = net::HttpServer::start(config.server, *service->hub_);
  if (!server) return Error{server.error()};
  service->server_ = std::move(*server);
  return service;
}

Service::~Service() { stop(); }

void Service::stop(std::chrono::milliseconds grace) {
  if (hub_) hub_->refuseNewSessions();
  if (server_) server_->shutdown(grace);
  if (hub_) hub_->stop();  // after the network: no frame is handed to a connection being torn down
  server_.reset();
  hub_.reset();
}

}  // namespace specula::app
