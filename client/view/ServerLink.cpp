#include "ServerLink.h"

#include <chrono>
#include <cstdio>

namespace specula::view {

Result<std::unique_ptr<client::ResumingClient>> connectToServer(const ViewerOptions& options) {
  v1::Hello hello;
  hello.set_protocol_version(1);
  hello.set_width(static_cast<std::uint32_t>(options.size.first));
  hello.set_height(static_cast<std::uint32_t>(options.size.second));
  return client::ResumingClient::connect(options.connection.address, options.connection.encoding, hello,
                                         options.connection.reconnect, [](const std::string& notice) {
                                           std::printf("specula-view: %s\n", notice.c_str());
                                           std::fflush(stdout);
                                         });
}

void runNetwork(client::ResumingClient& client, Link& link) {
  while (!link.stop) {
    std::deque<v1::ClientMessage> outgoing;
    {
      std::lock_guard lock(link.mutex);
      outgoing.swap(link.outgoing);
    }
    for (const v1::ClientMessage& message : outgoing)
      if (Status sent = client.send(message); !sent) {
        std::lock_guard lock(link.mutex);
        link.problem = sent.error();
      }
    auto message = client.receive(std::chrono::milliseconds(5));
    std::lock_guard lock(link.mutex);
    if (!message) {
      if (client.closeInfo()) {
        link.problem = "the server closed the connection: " + std::to_string(client.closeInfo()->code) + " " +
                       client.closeInfo()->reason;
        return;
      }
      continue;
    }
    if (message->has_error() && message->error().code() == v1::Error::RESUME_REFUSED)
      std::printf("specula-view: %s\n", message->error().message().c_str());
    else if (message->has_error()) link.problem = "server: " + message->error().message();
    if (message->has_frame()) {
      link.latestFrame = std::move(*message->mutable_frame());
      ++link.framesReceived;
    }
  }
}

}  // namespace specula::view
