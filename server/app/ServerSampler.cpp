#include "app/ServerSampler.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "app/LoopbackCluster.h"

namespace specula::app {

namespace {

// VmRSS of /proc/<pid>/status in MiB, or nullopt.
std::optional<double> residentMiB(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.starts_with("VmRSS:")) return std::strtod(line.c_str() + 6, nullptr) / 1024.0;  // "VmRSS:  1234 kB"
  return std::nullopt;
}

}  // namespace

std::optional<double> prometheusValue(std::string_view text, std::string_view name) {
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string_view line = text.substr(at, end - at);
    if (line.size() > name.size() && line.starts_with(name) && line[name.size()] == ' ')
      return std::strtod(std::string(line.substr(name.size() + 1)).c_str(), nullptr);
    at = end + 1;
  }
  return std::nullopt;
}

Result<ServerSample> sampleServer(pid_t pid, std::uint16_t port) {
  ServerSample sample;
  const auto rss = residentMiB(pid);
  if (!rss) return Error{"cannot read VmRSS from /proc/" + std::to_string(pid) + "/status: has the server exited?"};
  sample.rssMiB = *rss;
  std::error_code error;
  for (std::filesystem::directory_iterator fd("/proc/" + std::to_string(pid) + "/fd", error), end; !error && fd != end;
       fd.increment(error))
    ++sample.fds;
  if (error) return Error{"cannot list /proc/" + std::to_string(pid) + "/fd: " + error.message()};
  auto metrics = httpGet(port, "/metrics");
  if (!metrics) return Error{metrics.error()};
  if (metrics->first != 200) return Error{"GET /metrics answered " + std::to_string(metrics->first)};
  const std::pair<const char*, double*> wanted[] = {
      {"specula_gl_objects", &sample.glObjects},
      {"specula_sessions", &sample.sessions},
      {"specula_frames_sent_total", &sample.framesSent},
      {"specula_frames_skipped_total", &sample.framesSkipped},
      {"specula_write_timeouts_total", &sample.writeTimeouts},
      {"specula_sessions_opened_total", &sample.sessionsOpened},
      {"specula_sessions_resumed_total", &sample.sessionsResumed},
      {"specula_resumes_refused_total", &sample.resumesRefused},
  };
  for (const auto& [name, value] : wanted) {
    const auto found = prometheusValue(metrics->second, name);
    if (!found) return Error{std::string("/metrics lacks ") + name};
    *value = *found;
  }
  return sample;
}

}  // namespace specula::app
