#pragma once
// Several `specula serve` instances and an HAProxy front on loopback (issue #21), configured as a
// deployment is: the instances share a resume secret and drain on SIGTERM; HAProxy runs
// docker/haproxy/specula.cfg with a backend file listing them. `specula bench serve --instances`
// measures through it; the scale-out test kills and drains instances behind it.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/ChildProcess.h"
#include "app/PrivateFolder.h"
#include "base/Result.h"

namespace specula::app {

struct LoopbackClusterOptions {
  std::string specula;                      // the `specula` executable
  std::vector<std::string> serveArguments;  // added to each `serve` (scene, limits, GL)
  int instances = 3;
  std::string resumeSecret;  // >= 32 bytes; written to a file every instance reads
  int drainSeconds = 2;
  std::string haproxy = "haproxy";  // found on PATH unless a path is given
  std::filesystem::path haproxyConfig = "docker/haproxy/specula.cfg";
  std::chrono::milliseconds startTimeout{std::chrono::seconds(120)};  // an instance's GL start on a cold machine
};

class LoopbackCluster {
 public:
  // Starts the instances, then HAProxy, and waits until HAProxy sees every instance up. Fails naming
  // what did not start (HAProxy missing: the package to install) with its output.
  static Result<std::unique_ptr<LoopbackCluster>> start(const LoopbackClusterOptions& options);
  ~LoopbackCluster();  // stops everything it started and removes its files

  std::uint16_t frontPort() const { return frontPort_; }
  std::size_t instances() const { return instances_.size(); }
  std::uint16_t instancePort(std::size_t i) const { return instances_.at(i).port; }
  pid_t instancePid(std::size_t i) const { return instances_.at(i).process->pid(); }
  ChildProcess& instance(std::size_t i) { return *instances_.at(i).process; }

  void kill(std::size_t i);       // SIGKILL: the instance dies with its sessions open
  void terminate(std::size_t i);  // SIGTERM: it drains (--drain-seconds), closes its sessions with 1001 and exits
  // Open sessions on instance i (its /metrics), nullopt when it does not answer.
  std::optional<int> sessions(std::size_t i) const;
  // Waits until HAProxy reports exactly `up` of the instances UP; fails with their states on timeout.
  Status waitForUp(std::size_t up, std::chrono::milliseconds timeout) const;
  // One command on HAProxy's runtime API ("show stat", "set server specula/s2 state drain").
  Result<std::string> haproxyCommand(const std::string& command) const;

 private:
  struct Instance {
    std::unique_ptr<ChildProcess> process;
    std::uint16_t port = 0;
  };
  LoopbackCluster() = default;
  PrivateFolder folder_;  // secret, backend file, admin socket; removed after the processes stop
  std::vector<Instance> instances_;
  std::unique_ptr<ChildProcess> haproxy_;
  std::uint16_t frontPort_ = 0;
};

// GET `path` from 127.0.0.1:`port`: the status and body, or why it failed.
Result<std::pair<int, std::string>> httpGet(std::uint16_t port, const std::string& path,
                                            std::chrono::milliseconds timeout = std::chrono::seconds(3));

}  // namespace specula::app
