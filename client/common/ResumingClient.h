#pragma once
// A session that outlives its connection (issue #21): it keeps the latest resume token (from the
// welcome and, with stateless resume, from every frame), and when the connection drops or the server
// goes away it reconnects with backoff and says hello again with that token, so the session comes
// back with its camera, animation and settings, on the same instance or, behind a balancer, another.
// Blocking, one thread, like SpeculaClient.
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "SpeculaClient.h"

namespace specula::client {

struct ReconnectPolicy {
  int maxAttempts = 8;                        // tries per loss; then the loss is final
  std::chrono::milliseconds firstDelay{200};  // before the first try; doubled each try
  std::chrono::milliseconds maxDelay{5000};
  std::chrono::milliseconds connectTimeout{3000};  // one try: TCP, upgrade, welcome
  int receiveBufferBytes = 0;                      // each connection's (SpeculaClient::connect); 0: the system's
};

// Close codes after which a reconnect can succeed: the connection dropped (0, 1006), the server went
// away or restarts (1001, 1012), failed internally (1011) or is full or draining (1013). A normal
// close (1000) or a protocol complaint (1007, 1008, 1009) is final.
bool reconnectable(int closeCode);

class ResumingClient {
 public:
  // What happened to the connection, for the tool to tell its user ("reconnecting (attempt 2 of 8) in
  // 400 ms: ...", "resumed the session on a new connection").
  using Notice = std::function<void(const std::string&)>;

  // Connects and sends `hello`; the welcome arrives through receive() like any message.
  static Result<std::unique_ptr<ResumingClient>> connect(const ServerAddress& address, protocol::Encoding encoding,
                                                         v1::Hello hello, ReconnectPolicy policy = {},
                                                         Notice notice = {});

  // Sends on the current connection; a Resize also becomes the viewport of the next hello. A send
  // on a lost connection reconnects first.
  Status send(const v1::ClientMessage& message);
  // The next message. A reconnectable loss reconnects (taking as long as the policy allows) and
  // carries on with the new connection's welcome; fails on a timeout, on a final close (closeInfo()
  // says why) and once the attempts are used up.
  Result<v1::ServerMessage> receive(std::chrono::milliseconds timeout);
  std::optional<CloseInfo> closeInfo() const { return final_; }
  void close();
  // Drops the connection abruptly (SpeculaClient::abort); the next send or receive reconnects and resumes.
  void drop();

  const std::string& resumeToken() const { return token_; }
  int reconnects() const { return reconnects_; }  // successful ones

 private:
  ResumingClient(ServerAddress address, protocol::Encoding encoding, v1::Hello hello, ReconnectPolicy policy,
                 Notice notice)
      : address_(std::move(address)),
        encoding_(encoding),
        hello_(std::move(hello)),
        policy_(policy),
        notice_(std::move(notice)) {}
  Status open();                             // one connection and its hello
  Status reconnect(const std::string& why);  // tries until one connection works or the attempts are used up

  ServerAddress address_;
  protocol::Encoding encoding_;
  v1::Hello hello_;
  ReconnectPolicy policy_;
  Notice notice_;
  std::unique_ptr<SpeculaClient> client_;
  std::string token_;
  std::optional<CloseInfo> final_;
  int reconnects_ = 0;
};

}  // namespace specula::client
