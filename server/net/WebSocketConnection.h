#pragma once
// One WebSocket connection (internal to net): a strand, one read and one write in flight, an ordered
// control queue plus a one-frame latest-wins slot, a write deadline, and close codes.
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <deque>
#include <memory>
#include <optional>
#include <string>

#include "net/Connection.h"
#include "net/ConnectionRegistry.h"
#include "net/ServerOptions.h"

namespace specula::net {

class WebSocketConnection : public MessageSink, public std::enable_shared_from_this<WebSocketConnection> {
 public:
  using Request = boost::beast::http::request<boost::beast::http::empty_body>;

  WebSocketConnection(boost::beast::tcp_stream stream, const ServerOptions& options, ConnectionAcceptor& acceptor,
                      ConnectionRegistry& registry, std::shared_ptr<void> connectionToken);
  ~WebSocketConnection() override;

  // Completes the upgrade for `request` (already checked: path, token) answering `subprotocol`.
  void start(Request request, protocol::Encoding encoding, std::string subprotocol);

  void sendControl(std::string payload) override;
  void sendFrame(std::string payload) override;
  void close(CloseCode code, std::string reason) override;
  // Ends the connection now, without a close handshake: for shutdown, once no thread runs its handlers,
  // so the session it holds (and that holds it) is released.
  void abandon() { finish(); }

 private:
  struct PendingClose {
    CloseCode code;
    std::string reason;
  };

  void doRead();
  void onRead(boost::beast::error_code error, std::size_t bytes);
  void doWrite();
  void onWrite(boost::beast::error_code error, std::size_t bytes);
  void onClose(boost::beast::error_code error);
  void finish();

  boost::beast::websocket::stream<boost::beast::tcp_stream> ws_;
  boost::asio::steady_timer writeDeadline_;
  boost::asio::steady_timer firstMessageDeadline_;  // a silent client must not hold a session slot
  bool receivedMessage_ = false;
  const ServerOptions& options_;
  ConnectionAcceptor& acceptor_;
  ConnectionRegistry& registry_;
  std::shared_ptr<void> connectionToken_;  // counts this connection while it is open
  protocol::Encoding encoding_ = protocol::Encoding::Json;
  std::shared_ptr<ConnectionHandler> handler_;
  boost::beast::flat_buffer readBuffer_;
  // Strand-only state.
  std::deque<std::string> control_;
  std::optional<std::string> waitingFrame_;
  std::string writing_;  // the message being written; kept alive until its write completes
  bool writeInFlight_ = false;
  bool writingFrame_ = false;
  std::optional<PendingClose> pendingClose_;
  bool closing_ = false;
  bool finished_ = false;
};

}  // namespace specula::net
