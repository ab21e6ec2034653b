#pragma once
// What `specula bench soak` reads from outside a running `specula serve`: the kernel's view of the
// process (/proc/<pid>: resident memory, open file descriptors) and the service's own /metrics.
#include <sys/types.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "base/Result.h"

namespace specula::app {

struct ServerSample {
  double seconds = 0.0;  // since the clients started
  double rssMiB = 0.0;   // VmRSS
  double fds = 0.0;      // entries of /proc/<pid>/fd
  double glObjects = 0.0, sessions = 0.0;
  double framesSent = 0.0, framesSkipped = 0.0, writeTimeouts = 0.0;
  double sessionsOpened = 0.0, sessionsResumed = 0.0, resumesRefused = 0.0;
  std::uint64_t framesReceived = 0;  // by the clients, so far
};

// The value of the unlabelled sample `name` in Prometheus text, or nullopt when it is absent.
std::optional<double> prometheusValue(std::string_view text, std::string_view name);

// One sample of process `pid` serving /metrics on 127.0.0.1:`port`; fails naming what could not be read.
Result<ServerSample> sampleServer(pid_t pid, std::uint16_t port);

}  // namespace specula::app
