#include "net/WebSocketConnection.h"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

#include <boost/asio/dispatch.hpp>
#include <boost/asio/post.hpp>

namespace specula::net {

namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace asio = boost::asio;

WebSocketConnection::WebSocketConnection(beast::tcp_stream stream, const ServerOptions& options,
                                         ConnectionAcceptor& acceptor, ConnectionRegistry& registry,
                                         std::shared_ptr<void> connectionToken)
    : ws_(std::move(stream)),
      writeDeadline_(ws_.get_executor()),
      firstMessageDeadline_(ws_.get_executor()),
      options_(options),
      acceptor_(acceptor),
      registry_(registry),
      connectionToken_(std::move(connectionToken)) {}

WebSocketConnection::~WebSocketConnection() = default;

void WebSocketConnection::start(Request request, protocol::Encoding encoding, std::string subprotocol) {
  encoding_ = encoding;
  beast::get_lowest_layer(ws_).expires_never();  // the WebSocket's own timeouts take over
  websocket::stream_base::timeout timeouts{};
  timeouts.handshake_timeout = options_.handshakeTimeout;
  timeouts.idle_timeout = options_.idleTimeout;
  timeouts.keep_alive_pings = true;
  ws_.set_option(timeouts);
  const int unsentLimit = static_cast<int>(options_.unsentBytesLimit);
  // Best effort: a kernel without it queues as before, and the write deadline still bounds a stalled client.
  (void)::setsockopt(beast::get_lowest_layer(ws_).socket().native_handle(), IPPROTO_TCP, TCP_NOTSENT_LOWAT,
                     &unsentLimit, sizeof unsentLimit);
  // The size limit is enforced in onRead, not with read_message_max: Boost 1.74's teardown after that
  // limit can reset the connection before the client reads the 1009 close frame.
  ws_.read_message_max(0);
  ws_.set_option(websocket::stream_base::decorator([subprotocol](websocket::response_type& response) {
    response.set(beast::http::field::server, "specula");
    response.set(beast::http::field::sec_websocket_protocol, subprotocol);
  }));
  auto accepted = [self = shared_from_this()](beast::error_code error) {
    if (error) return self->finish();
    self->registry_.add(self);
    self->ws_.text(self->encoding_ == protocol::Encoding::Json);
    self->handler_ = self->acceptor_.accept({self->encoding_}, self);
    self->firstMessageDeadline_.expires_after(self->options_.firstMessageTimeout);
    self->firstMessageDeadline_.async_wait([weak = self->weak_from_this()](beast::error_code waited) {
      auto connection = weak.lock();
      if (waited || !connection || connection->receivedMessage_) return;
      connection->close(CloseCode::PolicyViolation, "no message within the first-message deadline");
    });
    self->doRead();
  };
  ws_.async_accept(request, std::move(accepted));
}

void WebSocketConnection::sendControl(std::string payload) {
  asio::post(ws_.get_executor(), [self = shared_from_this(), payload = std::move(payload)]() mutable {
    if (self->finished_ || self->closing_ || self->pendingClose_) return;
    if (self->control_.size() >= self->options_.maxQueuedControlMessages) {
      self->pendingClose_ = PendingClose{CloseCode::PolicyViolation, "too many unread replies"};
      self->control_.clear();
    } else {
      self->control_.push_back(std::move(payload));
    }
    self->doWrite();
  });
}

void WebSocketConnection::sendFrame(std::string payload) {
  asio::post(ws_.get_executor(), [self = shared_from_this(), payload = std::move(payload)]() mutable {
    if (self->finished_ || self->closing_ || self->pendingClose_) return;
    if (self->waitingFrame_ && self->handler_) self->handler_->onFrameReplaced();
    self->waitingFrame_ = std::move(payload);
    self->doWrite();
  });
}

void WebSocketConnection::close(CloseCode code, std::string reason) {
  asio::post(ws_.get_executor(), [self = shared_from_this(), code, reason = std::move(reason)]() mutable {
    if (self->finished_ || self->closing_ || self->pendingClose_) return;
    if (reason.size() > 120) reason.resize(120);  // a close frame's reason must fit in 123 bytes
    self->pendingClose_ = PendingClose{code, std::move(reason)};
    self->waitingFrame_.reset();
    self->doWrite();
  });
}

void WebSocketConnection::doRead() {
  // Never buffer more than one byte past the limit: enough to know a message is too big.
  const std::size_t room = options_.maxMessageBytes + 1 - readBuffer_.size();
  ws_.async_read_some(readBuffer_, room, beast::bind_front_handler(&WebSocketConnection::onRead, shared_from_this()));
}

void WebSocketConnection::onRead(beast::error_code error, std::size_t) {
  if (error) return finish();  // closed by the client, timed out, or torn down
  if (readBuffer_.size() > options_.maxMessageBytes) {
    readBuffer_.consume(readBuffer_.size());
    if (handler_) handler_->onOversizedMessage();
    // No more reads: the close handshake drains the rest of the message.
    return close(CloseCode::TooBig, "message over " + std::to_string(options_.maxMessageBytes) + " bytes");
  }
  if (!ws_.is_message_done()) return doRead();
  if (!receivedMessage_) {
    receivedMessage_ = true;
    firstMessageDeadline_.cancel();
  }
  if (handler_ && !closing_ && !pendingClose_) {
    const auto data = readBuffer_.cdata();
    handler_->onMessage(std::string_view(static_cast<const char*>(data.data()), data.size()), ws_.got_text());
  }
  readBuffer_.consume(readBuffer_.size());
  doRead();
}

void WebSocketConnection::doWrite() {
  if (writeInFlight_ || finished_ || closing_) return;
  writeDeadline_.expires_after(options_.writeTimeout);
  writeDeadline_.async_wait([weak = weak_from_this()](beast::error_code error) {
    auto self = weak.lock();
    if (error || !self || !self->writeInFlight_) return;
    if (self->handler_) self->handler_->onWriteTimedOut();
    beast::error_code ignored;
    beast::get_lowest_layer(self->ws_).socket().close(ignored);  // the client stopped reading: drop it
  });
  if (!control_.empty()) {
    writing_ = std::move(control_.front());
    control_.pop_front();
    writingFrame_ = false;
  } else if (waitingFrame_) {
    writing_ = std::move(*waitingFrame_);
    waitingFrame_.reset();
    writingFrame_ = true;
  } else if (pendingClose_) {
    closing_ = writeInFlight_ = true;
    websocket::close_reason reason(static_cast<websocket::close_code>(pendingClose_->code));
    reason.reason = pendingClose_->reason;
    ws_.async_close(reason, beast::bind_front_handler(&WebSocketConnection::onClose, shared_from_this()));
    return;
  } else {
    writeDeadline_.cancel();
    return;
  }
  writeInFlight_ = true;
  ws_.async_write(asio::buffer(writing_), beast::bind_front_handler(&WebSocketConnection::onWrite, shared_from_this()));
}

void WebSocketConnection::onWrite(beast::error_code error, std::size_t bytes) {
  writeInFlight_ = false;
  writeDeadline_.cancel();
  writing_.clear();
  if (error) return finish();
  if (writingFrame_ && handler_) handler_->onFrameSent(bytes);
  doWrite();
}

void WebSocketConnection::onClose(beast::error_code) {
  writeInFlight_ = false;
  finish();
}

void WebSocketConnection::finish() {
  if (finished_) return;
  finished_ = true;
  writeDeadline_.cancel();
  firstMessageDeadline_.cancel();
  control_.clear();
  waitingFrame_.reset();
  registry_.remove(this);
  beast::error_code ignored;
  beast::get_lowest_layer(ws_).socket().shutdown(asio::ip::tcp::socket::shutdown_both, ignored);
  beast::get_lowest_layer(ws_).socket().close(ignored);
  if (auto handler = std::move(handler_)) handler->onClosed();  // drops the session's reference cycle
}

}  // namespace specula::net
