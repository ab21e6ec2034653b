#pragma once
// The connection to the server, and the network thread that owns it.
#include <atomic>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "ResumingClient.h"
#include "ViewerOptions.h"

namespace specula::view {

// The network thread owns the client; the window thread talks to it only through this.
struct Link {
  std::mutex mutex;
  std::optional<v1::Frame> latestFrame;  // latest wins
  std::deque<v1::ClientMessage> outgoing;
  std::string problem;
  std::atomic<bool> stop{false};
  std::uint64_t framesReceived = 0;
};

// Connects with a hello for the window's size. A lost connection is retried and the session resumed
// (camera, animation, settings); each attempt is said on stdout.
Result<std::unique_ptr<client::ResumingClient>> connectToServer(const ViewerOptions& options);

// The network thread: sends what `link` queues, keeps the latest frame, and returns once `link.stop` is set
// or the server closed the connection (said in `link.problem`).
void runNetwork(client::ResumingClient& client, Link& link);

}  // namespace specula::view
