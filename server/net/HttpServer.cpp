#include "net/HttpServer.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/strand.hpp>
#include <mutex>
#include <thread>
#include <vector>

#include "net/ConnectionRegistry.h"
#include "net/HttpConnection.h"
#include "net/StaticFiles.h"

namespace specula::net {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;

bool isLoopbackAddress(const std::string& address) {
  if (address == "localhost") return true;
  boost::system::error_code error;
  const auto parsed = asio::ip::make_address(address, error);
  return !error && parsed.is_loopback();
}

std::optional<std::string> bindProblem(const ServerOptions& options) {
  if (isLoopbackAddress(options.bindAddress) || !options.token.empty()) return std::nullopt;
  return "refusing to serve on " + options.bindAddress +
         " without a token: anyone who can reach it could use it. Pass --token SECRET (or set SPECULA_TOKEN; "
         "clients add ?token=SECRET) or bind 127.0.0.1";
}

struct HttpServer::State {
  ServerOptions options;
  ConnectionAcceptor& acceptor;
  StaticFiles files;
  ConnectionRegistry registry;
  asio::io_context io;
  tcp::acceptor listener;
  std::vector<std::thread> threads;
  std::once_flag shutdownOnce;

  State(ServerOptions options_, ConnectionAcceptor& acceptor_)
      : options(std::move(options_)), acceptor(acceptor_), files(options.webRoot), listener(asio::make_strand(io)) {}

  void doAccept() {
    listener.async_accept(asio::make_strand(io), [this](boost::system::error_code error, tcp::socket socket) {
      if (error == asio::error::operation_aborted || !listener.is_open()) return;
      if (!error) {
        if (registry.openConnections() >= options.maxConnections) {
          boost::system::error_code ignored;
          socket.close(ignored);  // over the connection cap: refuse before reading a byte
        } else {
          std::make_shared<HttpConnection>(std::move(socket), options, files, acceptor, registry)->start();
        }
      }
      doAccept();
    });
  }
};

HttpServer::HttpServer(std::unique_ptr<State> state) : state_(std::move(state)) {}

HttpServer::~HttpServer() { shutdown(std::chrono::milliseconds(1000)); }

Result<std::unique_ptr<HttpServer>> HttpServer::start(ServerOptions options, ConnectionAcceptor& acceptor,
                                                      int ioThreads) {
  if (auto problem = bindProblem(options)) return Error{*problem};
  boost::system::error_code error;
  const std::string host = options.bindAddress == "localhost" ? "127.0.0.1" : options.bindAddress;
  const auto address = asio::ip::make_address(host, error);
  if (error) return Error{"--bind: '" + options.bindAddress + "' is not an IP address (e.g. 127.0.0.1 or 0.0.0.0)"};
  const tcp::endpoint endpoint(address, options.port);
  auto state = std::make_unique<State>(std::move(options), acceptor);
  const std::string where = host + ":" + std::to_string(endpoint.port());
  state->listener.open(endpoint.protocol(), error);
  if (!error) state->listener.set_option(asio::socket_base::reuse_address(true), error);
  if (!error) state->listener.bind(endpoint, error);
  if (!error) state->listener.listen(asio::socket_base::max_listen_connections, error);
  if (error)
    return Error{"cannot listen on " + where + ": " + error.message() +
                 " (is another server on that port? choose another with --port, or 0 for any free port)"};
  state->doAccept();
  for (int i = 0; i < std::max(1, ioThreads); ++i) state->threads.emplace_back([io = &state->io] { io->run(); });
  return std::unique_ptr<HttpServer>(new HttpServer(std::move(state)));
}

std::uint16_t HttpServer::port() const {
  boost::system::error_code error;
  const auto endpoint = state_->listener.local_endpoint(error);
  return error ? 0 : endpoint.port();
}

std::size_t HttpServer::openWebSockets() const { return state_->registry.size(); }
std::size_t HttpServer::openConnections() const { return state_->registry.openConnections(); }

void HttpServer::shutdown(std::chrono::milliseconds grace, CloseCode code) {
  std::call_once(state_->shutdownOnce, [&] {
    asio::post(state_->listener.get_executor(), [state = state_.get()] {
      boost::system::error_code ignored;
      state->listener.close(ignored);
    });
    state_->registry.closeAll(code, code == CloseCode::GoingAway ? "server shutting down" : "server closing");
    const auto deadline = std::chrono::steady_clock::now() + grace;
    while (state_->registry.size() > 0 && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    state_->io.stop();
    for (std::thread& thread : state_->threads) thread.join();
    state_->registry.abandonAll();  // those whose close handshake outlasted the grace
  });
}

}  // namespace specula::net
