#include "ResumingClient.h"

#include <algorithm>
#include <thread>

namespace specula::client {

bool reconnectable(int closeCode) {
  return closeCode == 0 || closeCode == 1001 || closeCode == 1006 || closeCode == 1011 || closeCode == 1012 ||
         closeCode == 1013;
}

Result<std::unique_ptr<ResumingClient>> ResumingClient::connect(const ServerAddress& address,
                                                                protocol::Encoding encoding, v1::Hello hello,
                                                                ReconnectPolicy policy, Notice notice) {
  std::unique_ptr<ResumingClient> client(
      new ResumingClient(address, encoding, std::move(hello), policy, std::move(notice)));
  if (Status opened = client->open(); !opened) return Error{opened.error()};
  return client;
}

Status ResumingClient::open() {
  auto connected = SpeculaClient::connect(address_, encoding_, policy_.connectTimeout, policy_.receiveBufferBytes);
  if (!connected) return Error{connected.error()};
  client_ = std::move(*connected);
  v1::ClientMessage hello;
  *hello.mutable_hello() = hello_;
  hello.mutable_hello()->set_resume_token(token_);
  return client_->send(hello);
}

Status ResumingClient::reconnect(const std::string& why) {
  client_.reset();
  std::chrono::milliseconds delay = policy_.firstDelay;
  std::string last = why;
  for (int attempt = 1; attempt <= policy_.maxAttempts; ++attempt) {
    if (notice_)
      notice_("connection lost (" + last + "): reconnecting (attempt " + std::to_string(attempt) + " of " +
              std::to_string(policy_.maxAttempts) + ") in " + std::to_string(delay.count()) + " ms" +
              (token_.empty() ? "" : ", to resume the session"));
    std::this_thread::sleep_for(delay);
    delay = std::min(policy_.maxDelay, 2 * delay);
    if (Status opened = open(); !opened) {
      last = opened.error();
      client_.reset();
      continue;
    }
    ++reconnects_;
    return {};
  }
  final_ = CloseInfo{0, "gave up after " + std::to_string(policy_.maxAttempts) + " reconnect attempts: " + last};
  if (notice_) notice_(final_->reason);
  return Error{final_->reason};
}

Status ResumingClient::send(const v1::ClientMessage& message) {
  if (final_) return Error{"the session is over: " + final_->reason};
  if (message.has_resize()) {
    hello_.set_width(message.resize().width());
    hello_.set_height(message.resize().height());
  }
  if (!client_)
    if (Status back = reconnect("not connected"); !back) return back;
  Status sent = client_->send(message);
  if (sent || !client_->closeInfo() || !reconnectable(client_->closeInfo()->code)) return sent;
  if (Status back = reconnect("send failed: " + sent.error()); !back) return back;
  return client_->send(message);
}

Result<v1::ServerMessage> ResumingClient::receive(std::chrono::milliseconds timeout) {
  if (final_) return Error{"the session is over: " + final_->reason};
  if (!client_)
    if (Status back = reconnect("not connected"); !back) return Error{back.error()};
  while (true) {
    auto message = client_->receive(timeout);
    if (message) {
      if (message->has_welcome()) {
        if (reconnects_ > 0 && notice_)
          notice_(message->welcome().resumed()
                      ? "resumed the session on a new connection (camera, animation and settings kept)"
                      : "reconnected, but as a fresh session (the server could not resume the old one)");
        token_ = message->welcome().resume_token();
      }
      if (message->has_frame() && !message->frame().resume_token().empty()) token_ = message->frame().resume_token();
      return message;
    }
    const std::optional<CloseInfo> closed = client_->closeInfo();
    if (!closed) return message;  // a timeout or an undecodable message: the connection is still there
    if (!reconnectable(closed->code)) {
      final_ = closed;
      return Error{message.error()};
    }
    const std::string why =
        closed->code == 0 ? closed->reason : "close " + std::to_string(closed->code) + " " + closed->reason;
    if (Status back = reconnect(why); !back) return Error{back.error()};
  }
}

void ResumingClient::drop() {
  if (client_) client_->abort();
  client_.reset();
}

void ResumingClient::close() {
  if (client_) client_->close();
  if (!final_) final_ = CloseInfo{1000, "closed by the client"};
}

}  // namespace specula::client
