#pragma once
// One TCP connection before (or instead of) a WebSocket upgrade (internal to net): reads HTTP
// requests under a deadline and answers /, /healthz and /metrics, or hands /ws to a WebSocketConnection.
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <memory>
#include <optional>

#include "net/Connection.h"
#include "net/ConnectionRegistry.h"
#include "net/ServerOptions.h"
#include "net/StaticFiles.h"

namespace specula::net {

class HttpConnection : public std::enable_shared_from_this<HttpConnection> {
 public:
  HttpConnection(boost::asio::ip::tcp::socket socket, const ServerOptions& options, const StaticFiles& files,
                 ConnectionAcceptor& acceptor, ConnectionRegistry& registry);
  void start();

 private:
  using Response = boost::beast::http::response<boost::beast::http::string_body>;

  void doRead();
  void onRead(boost::beast::error_code error, std::size_t bytes);
  Response respond(const boost::beast::http::request<boost::beast::http::empty_body>& request) const;
  void onWrite(bool keepAlive, boost::beast::error_code error, std::size_t bytes);
  void closeSocket();

  boost::beast::tcp_stream stream_;
  boost::beast::flat_buffer buffer_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::empty_body>> parser_;
  std::shared_ptr<Response> response_;
  const ServerOptions& options_;
  const StaticFiles& files_;
  ConnectionAcceptor& acceptor_;
  ConnectionRegistry& registry_;
  std::shared_ptr<void> connectionToken_;  // counts this connection while it is open
};

}  // namespace specula::net
