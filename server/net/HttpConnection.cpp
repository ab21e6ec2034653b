#include "net/HttpConnection.h"

#include <boost/beast/websocket.hpp>
#include <string>

#include "base/UrlEncoding.h"
#include "net/RequestTarget.h"
#include "net/WebSocketConnection.h"

namespace specula::net {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;

namespace {

constexpr std::uint32_t kMaxHeaderBytes = 8 * 1024;

// Boost 1.74's string_view is its own type.
std::string_view standard(boost::beast::string_view text) { return {text.data(), text.size()}; }

// Compares without an early exit, so response time does not reveal how much of a guess was right.
bool equalInConstantTime(std::string_view given, std::string_view expected) {
  if (given.size() != expected.size() || expected.empty()) return false;
  unsigned difference = 0;
  for (std::size_t i = 0; i < given.size(); ++i)
    difference |= static_cast<unsigned char>(given[i]) ^ static_cast<unsigned char>(expected[i]);
  return difference == 0;
}

bool authorized(const http::request<http::empty_body>& request, const std::string& token) {
  if (token.empty()) return true;
  std::string_view bearer = standard(request[http::field::authorization]);
  if (bearer.starts_with("Bearer ")) bearer.remove_prefix(7);
  else bearer = {};
  return equalInConstantTime(percentDecoded(queryValue(standard(request.target()), "token")), token) ||
         equalInConstantTime(bearer, token);
}

// The first subprotocol we speak from the client's comma-separated list, or nullopt.
std::optional<std::pair<protocol::Encoding, std::string>> chooseSubprotocol(std::string_view offered) {
  while (!offered.empty()) {
    const std::size_t comma = offered.find(',');
    std::string_view name = offered.substr(0, comma);
    while (!name.empty() && name.front() == ' ') name.remove_prefix(1);
    while (!name.empty() && name.back() == ' ') name.remove_suffix(1);
    for (const protocol::Encoding encoding : {protocol::Encoding::Proto, protocol::Encoding::Json})
      if (name == protocol::subprotocolName(encoding)) return std::pair{encoding, std::string(name)};
    if (comma == std::string_view::npos) break;
    offered.remove_prefix(comma + 1);
  }
  return std::nullopt;
}

}  // namespace

HttpConnection::HttpConnection(boost::asio::ip::tcp::socket socket, const ServerOptions& options,
                               const StaticFiles& files, ConnectionAcceptor& acceptor, ConnectionRegistry& registry)
    : stream_(std::move(socket)),
      options_(options),
      files_(files),
      acceptor_(acceptor),
      registry_(registry),
      connectionToken_(registry.openConnection()) {}

void HttpConnection::start() { doRead(); }

void HttpConnection::doRead() {
  parser_.emplace();
  parser_->header_limit(kMaxHeaderBytes);
  stream_.expires_after(options_.handshakeTimeout);
  http::async_read(stream_, buffer_, *parser_, beast::bind_front_handler(&HttpConnection::onRead, shared_from_this()));
}

void HttpConnection::onRead(beast::error_code error, std::size_t) {
  if (error) return closeSocket();  // closed, timed out or malformed: nothing worth answering
  http::request<http::empty_body> request = parser_->release();
  const std::string_view path = targetPath(standard(request.target()));
  if (websocket::is_upgrade(request) && path == "/ws" && authorized(request, options_.token)) {
    if (auto chosen = chooseSubprotocol(standard(request[http::field::sec_websocket_protocol]))) {
      auto ws = std::make_shared<WebSocketConnection>(std::move(stream_), options_, acceptor_, registry_,
                                                      std::move(connectionToken_));
      ws->start(std::move(request), chosen->first, std::move(chosen->second));
      return;
    }
  }
  response_ = std::make_shared<Response>(respond(request));
  const bool keepAlive = response_->keep_alive();
  http::async_write(stream_, *response_,
                    beast::bind_front_handler(&HttpConnection::onWrite, shared_from_this(), keepAlive));
}

HttpConnection::Response HttpConnection::respond(const http::request<http::empty_body>& request) const {
  const std::string_view path = targetPath(standard(request.target()));
  auto answer = [&](http::status status, std::string body, std::string contentType = "text/plain; charset=utf-8") {
    Response response{status, request.version()};
    response.set(http::field::server, "specula");
    response.set(http::field::content_type, contentType);
    response.set(http::field::cache_control, "no-cache");
    response.set("X-Content-Type-Options", "nosniff");
    response.keep_alive(request.keep_alive());
    if (request.method() != http::verb::head) response.body() = std::move(body);
    response.prepare_payload();
    return response;
  };
  if (request.method() != http::verb::get && request.method() != http::verb::head)
    return answer(http::status::method_not_allowed, "only GET and HEAD are served\n");
  if (path == "/healthz") return answer(http::status::ok, "ok\n");
  if (path == "/readyz") {  // for balancers: liveness is /healthz, this says whether to send new sessions here
    const std::optional<std::string> reason = options_.notReady ? options_.notReady() : std::nullopt;
    return reason ? answer(http::status::service_unavailable, *reason + "\n") : answer(http::status::ok, "ready\n");
  }
  if (path == "/metrics" && options_.metricsText && options_.publicMetrics)
    return answer(http::status::ok, options_.metricsText(), "text/plain; version=0.0.4; charset=utf-8");
  if (!authorized(request, options_.token))
    return answer(http::status::unauthorized,
                  "this server needs its token: add ?token=SECRET to the URL or send 'Authorization: Bearer SECRET'\n");
  if (path == "/ws") {
    if (!websocket::is_upgrade(request))
      return answer(http::status::upgrade_required, "/ws is the WebSocket endpoint: connect with a WebSocket client\n");
    return answer(http::status::bad_request,
                  "choose a subprotocol: Sec-WebSocket-Protocol: " +
                      std::string(protocol::subprotocolName(protocol::Encoding::Json)) + " or " +
                      std::string(protocol::subprotocolName(protocol::Encoding::Proto)) + "\n");
  }
  if (path == "/metrics" && options_.metricsText)
    return answer(http::status::ok, options_.metricsText(), "text/plain; version=0.0.4; charset=utf-8");
  if (auto document = options_.jsonDocuments.find(path); document != options_.jsonDocuments.end())
    return answer(http::status::ok, document->second, "application/json");
  if (auto file = files_.find(path)) return answer(http::status::ok, std::move(file->body), file->contentType);
  return answer(http::status::not_found, "not found: " + std::string(path) +
                                             " (routes: / the browser client, /healthz, /readyz, /metrics, /ws)\n");
}

void HttpConnection::onWrite(bool keepAlive, beast::error_code error, std::size_t) {
  response_.reset();
  if (error || !keepAlive) return closeSocket();
  doRead();
}

void HttpConnection::closeSocket() {
  beast::error_code ignored;
  stream_.socket().shutdown(boost::asio::ip::tcp::socket::shutdown_send, ignored);
  stream_.close();
}

}  // namespace specula::net
