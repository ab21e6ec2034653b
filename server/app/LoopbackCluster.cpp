#include "app/LoopbackCluster.h"

#include <signal.h>
#include <stdlib.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/local/stream_protocol.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <fstream>
#include <sstream>
#include <thread>

namespace specula::app {

namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace fs = std::filesystem;
using namespace std::chrono_literals;

// A port no one listens on now (the kernel's pick for a socket bound to port 0, released at once).
Result<std::uint16_t> freePort() {
  asio::io_context io;
  asio::ip::tcp::acceptor acceptor(io);
  boost::system::error_code error;
  acceptor.open(asio::ip::tcp::v4(), error);
  if (!error) acceptor.bind({asio::ip::make_address("127.0.0.1"), 0}, error);
  if (error) return Error{"cannot find a free loopback port: " + error.message()};
  return acceptor.local_endpoint().port();
}

// The path of `program` found on PATH (or itself when it names a path), or nullopt.
std::optional<std::string> findProgram(const std::string& program) {
  if (program.find('/') != std::string::npos) return fs::exists(program) ? std::optional(program) : std::nullopt;
  const char* path = std::getenv("PATH");
  std::stringstream folders(path ? path : "/usr/sbin:/usr/bin");
  for (std::string folder; std::getline(folders, folder, ':');)
    if (!folder.empty() && fs::exists(fs::path(folder) / program)) return (fs::path(folder) / program).string();
  for (const char* folder : {"/usr/sbin", "/sbin"})  // Debian puts haproxy in sbin, off a user's PATH
    if (fs::exists(fs::path(folder) / program)) return (fs::path(folder) / program).string();
  return std::nullopt;
}

}  // namespace

Result<std::pair<int, std::string>> httpGet(std::uint16_t port, const std::string& path,
                                            std::chrono::milliseconds timeout) {
  asio::io_context io;
  beast::tcp_stream stream(io);
  stream.expires_after(timeout);
  beast::http::request<beast::http::empty_body> request{beast::http::verb::get, path, 11};
  request.set(beast::http::field::host, "127.0.0.1");
  beast::http::response<beast::http::string_body> response;
  beast::flat_buffer buffer;
  beast::error_code failure;
  stream.async_connect(asio::ip::tcp::endpoint(asio::ip::make_address("127.0.0.1"), port),
                       [&](beast::error_code error) {
                         if (error) return void(failure = error);
                         beast::http::async_write(stream, request, [&](beast::error_code written, std::size_t) {
                           if (written) return void(failure = written);
                           beast::http::async_read(stream, buffer, response,
                                                   [&](beast::error_code read, std::size_t) { failure = read; });
                         });
                       });
  io.run();
  if (failure) return Error{"GET http://127.0.0.1:" + std::to_string(port) + path + ": " + failure.message()};
  return std::pair{static_cast<int>(response.result_int()), response.body()};
}

Result<std::unique_ptr<LoopbackCluster>> LoopbackCluster::start(const LoopbackClusterOptions& options) {
  const std::optional<std::string> haproxy = findProgram(options.haproxy);
  if (!haproxy)
    return Error{"'" + options.haproxy +
                 "' is not installed: apt-get install haproxy (docker/install-deps.sh installs it)"};
  if (!fs::exists(options.haproxyConfig))
    return Error{"HAProxy's configuration " + options.haproxyConfig.string() +
                 " is missing; run from the repository root or name it"};
  std::unique_ptr<LoopbackCluster> cluster(new LoopbackCluster());
  auto folder = PrivateFolder::create("specula-cluster-");
  if (!folder) return Error{"the cluster's files: " + folder.error()};
  cluster->folder_ = std::move(*folder);
  const fs::path secret = cluster->folder_.writeSecret("resume.secret", options.resumeSecret);

  for (int i = 0; i < options.instances; ++i) {
    std::vector<std::string> arguments = {options.specula,
                                          "serve",
                                          "--port",
                                          "0",
                                          "--public-metrics",
                                          "--resume-secret-file",
                                          secret.string(),
                                          "--drain-seconds",
                                          std::to_string(options.drainSeconds)};
    arguments.insert(arguments.end(), options.serveArguments.begin(), options.serveArguments.end());
    auto process = ChildProcess::start(std::move(arguments));
    if (!process) return Error{"instance " + std::to_string(i) + ": " + process.error()};
    cluster->instances_.push_back({std::move(*process), 0});
  }
  for (std::size_t i = 0; i < cluster->instances_.size(); ++i) {  // they start their GL side by side
    Instance& instance = cluster->instances_[i];
    const auto listening =
        instance.process->waitFor(std::regex("listening on 127\\.0\\.0\\.1:(\\d+)"), options.startTimeout);
    if (!listening) return Error{"instance " + std::to_string(i) + " did not start:\n" + instance.process->output()};
    instance.port = static_cast<std::uint16_t>(std::stoi((*listening)[1]));
  }

  std::string backend = "# Written by specula's LoopbackCluster for this run.\nbackend specula from specula\n";
  for (std::size_t i = 0; i < cluster->instances_.size(); ++i)
    backend += "    server s" + std::to_string(i) + " 127.0.0.1:" + std::to_string(cluster->instances_[i].port) + "\n";
  const fs::path backendFile = cluster->folder_.path() / "backend.cfg";
  std::ofstream(backendFile) << backend;
  auto front = freePort();
  if (!front) return Error{front.error()};
  cluster->frontPort_ = *front;
  auto process =
      ChildProcess::start({*haproxy, "-db", "-f", options.haproxyConfig.string(), "-f", backendFile.string()},
                          {{"SPECULA_FRONT_BIND", "127.0.0.1:" + std::to_string(*front)},
                           {"SPECULA_HAPROXY_SOCKET", (cluster->folder_.path() / "admin.sock").string()}});
  if (!process) return Error{"HAProxy: " + process.error()};
  cluster->haproxy_ = std::move(*process);
  if (Status up = cluster->waitForUp(cluster->instances_.size(), 15s); !up)
    return Error{up.error() + "\nHAProxy's output:\n" + cluster->haproxy_->output()};
  return cluster;
}

LoopbackCluster::~LoopbackCluster() {
  haproxy_.reset();
  instances_.clear();
}

void LoopbackCluster::kill(std::size_t i) {
  instances_.at(i).process->signal(SIGKILL);
  instances_.at(i).process->waitExit(5s);
}

void LoopbackCluster::terminate(std::size_t i) { instances_.at(i).process->signal(SIGTERM); }

std::optional<int> LoopbackCluster::sessions(std::size_t i) const {
  auto metrics = httpGet(instances_.at(i).port, "/metrics");
  if (!metrics || metrics->first != 200) return std::nullopt;
  const std::string& text = metrics->second;
  const std::size_t at = text.find("\nspecula_sessions ");
  if (at == std::string::npos) return std::nullopt;
  return static_cast<int>(std::strtol(text.c_str() + at + std::string("\nspecula_sessions ").size(), nullptr, 10));
}

Result<std::string> LoopbackCluster::haproxyCommand(const std::string& command) const {
  asio::io_context io;
  asio::local::stream_protocol::socket socket(io);
  boost::system::error_code error;
  socket.connect((folder_.path() / "admin.sock").string(), error);
  if (error) return Error{"HAProxy's runtime API: " + error.message()};
  asio::write(socket, asio::buffer(command + "\n"), error);
  if (error) return Error{"HAProxy's runtime API: " + error.message()};
  std::string reply;
  asio::read(socket, asio::dynamic_buffer(reply), error);  // it answers, then closes
  if (error && error != asio::error::eof) return Error{"HAProxy's runtime API: " + error.message()};
  return reply;
}

Status LoopbackCluster::waitForUp(std::size_t up, std::chrono::milliseconds timeout) const {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::string states;
  while (true) {
    // "show stat" is CSV: proxy name, server name, ..., status (the 18th column).
    std::size_t seen = 0;
    states.clear();
    if (auto stat = haproxyCommand("show stat")) {
      std::stringstream lines(*stat);
      for (std::string line; std::getline(lines, line);) {
        std::vector<std::string> fields;
        std::stringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
        if (fields.size() < 18 || fields[0] != "specula" || fields[1] == "FRONTEND" || fields[1] == "BACKEND") continue;
        states += " " + fields[1] + " " + fields[17];
        seen += fields[17] == "UP" ? 1 : 0;
      }
    } else {
      states = " " + stat.error();
    }
    if (seen == up) return {};
    if (std::chrono::steady_clock::now() >= deadline)
      return Error{"HAProxy did not see " + std::to_string(up) + " instances up in time; it reports:" + states};
    std::this_thread::sleep_for(100ms);
  }
}

}  // namespace specula::app
