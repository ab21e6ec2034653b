#include "app/ChildProcess.h"

#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

extern char** environ;

namespace specula::app {

namespace {
constexpr std::size_t kKeptOutputBytes = 256 * 1024;
}  // namespace

Result<std::unique_ptr<ChildProcess>> ChildProcess::start(
    std::vector<std::string> arguments, std::vector<std::pair<std::string, std::string>> environment) {
  if (arguments.empty()) return Error{"no program to start"};
  // Everything exec needs is built before fork: after it, in a threaded parent, only async-signal-safe calls are
  // allowed.
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  std::vector<std::string> variables;
  for (char** variable = environ; *variable; ++variable) variables.emplace_back(*variable);
  for (const auto& [name, value] : environment) variables.push_back(name + "=" + value);
  std::vector<char*> envp;
  for (std::string& variable : variables) envp.push_back(variable.data());
  envp.push_back(nullptr);
  int fds[2];
  if (pipe(fds) != 0) return Error{std::string("cannot create a pipe: ") + std::strerror(errno)};
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    return Error{std::string("cannot fork: ") + std::strerror(errno)};
  }
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // a harness that crashes takes its instances and HAProxy with it
    sigset_t none;                     // the child starts with no signal blocked, whatever the parent's threads block
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    dup2(fds[1], STDOUT_FILENO);
    dup2(fds[1], STDERR_FILENO);
    close(fds[0]);
    close(fds[1]);
    execve(argv[0], argv.data(), envp.data());
    _exit(127);
  }
  close(fds[1]);
  return std::unique_ptr<ChildProcess>(new ChildProcess(pid, fds[0]));
}

ChildProcess::ChildProcess(pid_t pid, int output) : pid_(pid), output_(output) {
  reader_ = std::thread([this] { collect(); });
}

ChildProcess::~ChildProcess() {
  if (!status_) {
    ::kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  // The pipe closes once nothing holds its write end; a grandchild could, so the reader is told too.
  if (reader_.joinable()) {
    {
      std::lock_guard lock(mutex_);
      closed_ = true;
    }
    reader_.join();
  }
  close(output_);
}

void ChildProcess::collect() {
  char buffer[4096];
  while (true) {
    {
      std::lock_guard lock(mutex_);
      if (closed_) return;
    }
    pollfd fd{output_, POLLIN, 0};
    if (poll(&fd, 1, 50) <= 0) continue;
    const ssize_t count = read(output_, buffer, sizeof buffer);
    std::lock_guard lock(mutex_);
    if (count <= 0) {
      closed_ = true;
      return;
    }
    text_.append(buffer, static_cast<std::size_t>(count));
    if (text_.size() > 2 * kKeptOutputBytes) text_.erase(0, text_.size() - kKeptOutputBytes);
  }
}

void ChildProcess::signal(int number) const {
  if (!status_) ::kill(pid_, number);
}

std::optional<std::vector<std::string>> ChildProcess::waitFor(const std::regex& pattern,
                                                              std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true) {
    {
      std::lock_guard lock(mutex_);
      std::smatch match;
      if (std::regex_search(text_, match, pattern)) return std::vector<std::string>(match.begin(), match.end());
      if (closed_) return std::nullopt;
    }
    if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

std::optional<int> ChildProcess::waitExit(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!status_) {
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      break;
    }
    if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  // What it wrote last is read before anyone looks at it.
  for (int i = 0; i < 10; ++i) {
    {
      std::lock_guard lock(mutex_);
      if (closed_) break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return status_;
}

std::string ChildProcess::output() const {
  std::lock_guard lock(mutex_);
  return text_;
}

}  // namespace specula::app
