#pragma once
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>

namespace specula::net {

// Everything the network layer needs to know; defaults are the service's.
struct ServerOptions {
  std::string bindAddress = "127.0.0.1";
  std::uint16_t port = 8080;  // 0: any free port (HttpServer::port() tells which)
  std::string token;          // non-empty: every route but /healthz and /readyz (and /metrics when public) demands it
  std::filesystem::path webRoot;            // files served at / (index.html for "/"); empty: none
  std::size_t maxMessageBytes = 64 * 1024;  // client WebSocket messages; larger closes with 1009
  std::size_t maxConnections = 256;         // open TCP connections; more are closed at once
  std::size_t maxQueuedControlMessages = 64;
  // Unsent bytes a WebSocket's kernel buffer may hold (TCP_NOTSENT_LOWAT). Past it a write waits, so a slow
  // reader's newer frames replace the waiting one (latest wins) instead of queueing in a socket buffer that
  // autotunes to megabytes, seconds of stale frames; bytes in flight are not counted, so throughput is not capped.
  std::size_t unsentBytesLimit = 128 * 1024;
  std::chrono::milliseconds handshakeTimeout{5000};     // HTTP request or WebSocket upgrade
  std::chrono::milliseconds writeTimeout{5000};         // one message to a client that stopped reading
  std::chrono::milliseconds firstMessageTimeout{5000};  // from the upgrade to the client's first message
  std::chrono::milliseconds idleTimeout{60000};         // no data (pings answered count) from the client
  std::function<std::string()> metricsText;             // GET /metrics body (Prometheus text format)
  // Documents the service writes (path → JSON body), served beside the web root's files.
  std::map<std::string, std::string, std::less<>> jsonDocuments;
  bool publicMetrics = false;  // /metrics without the token (a scraper inside the cluster)
  // GET /readyz: why no new session is taken now ("full", "draining": 503), or nullopt (200 "ready").
  std::function<std::optional<std::string>()> notReady;
};

// True for 127.0.0.0/8, ::1 and "localhost": the addresses that need no token.
bool isLoopbackAddress(const std::string& address);
// Why these options must not serve (a non-loopback bind without a token), or nullopt.
std::optional<std::string> bindProblem(const ServerOptions& options);

}  // namespace specula::net
