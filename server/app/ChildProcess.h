#pragma once
// A child process with its stdout and stderr collected (by a thread, so a chatty child never blocks
// on a full pipe): what `specula bench serve --instances` and the tests start instances and HAProxy with.
#include <sys/types.h>

#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <regex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "base/Result.h"

namespace specula::app {

class ChildProcess {
 public:
  // Runs arguments[0] (a path) with the rest, with this process's environment plus `environment`.
  static Result<std::unique_ptr<ChildProcess>> start(std::vector<std::string> arguments,
                                                     std::vector<std::pair<std::string, std::string>> environment = {});
  ~ChildProcess();  // SIGKILL if it still runs, then reaps it
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  void signal(int number) const;
  // The output's first match of `pattern`, its groups in order (0: the whole match), waiting up to
  // `timeout`; nullopt when the time passed or the process ended first.
  std::optional<std::vector<std::string>> waitFor(const std::regex& pattern, std::chrono::milliseconds timeout);
  // The exit status once it ended (-1 when a signal ended it); nullopt when it still runs after `timeout`.
  std::optional<int> waitExit(std::chrono::milliseconds timeout);
  std::string output() const;  // the last 256 KiB of stdout and stderr, interleaved

 private:
  ChildProcess(pid_t pid, int output);
  void collect();

  pid_t pid_;
  int output_;
  std::optional<int> status_;
  mutable std::mutex mutex_;
  std::string text_;
  bool closed_ = false;  // the pipe ended: the child and anything it started are gone
  std::thread reader_;
};

}  // namespace specula::app
