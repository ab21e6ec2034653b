#include "SpeculaClient.h"

#include "base/UrlEncoding.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

namespace specula::client {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

Result<ServerAddress> parseServerUrl(const std::string& url) {
  std::string rest = url;
  for (const char* scheme : {"ws://", "http://"})
    if (rest.rfind(scheme, 0) == 0) rest = rest.substr(std::string(scheme).size());
  if (rest.rfind("wss://", 0) == 0 || rest.rfind("https://", 0) == 0)
    return Error{"'" + url + "': TLS is not supported; put a TLS proxy in front and use ws:// here"};
  ServerAddress address;
  const std::size_t query = rest.find('?');
  if (query != std::string::npos) {
    const std::string parameters = rest.substr(query + 1);
    const std::size_t token = parameters.find("token=");
    if (token != std::string::npos)
      address.token = percentDecoded(parameters.substr(token + 6, parameters.find('&', token) - token - 6));
    rest = rest.substr(0, query);
  }
  rest = rest.substr(0, rest.find('/'));
  const std::size_t colon = rest.rfind(':');
  if (rest.empty() || colon == 0) return Error{"'" + url + "': expected ws://HOST:PORT (e.g. ws://127.0.0.1:8080)"};
  address.host = rest.substr(0, colon);
  if (colon != std::string::npos) {
    const std::string port = rest.substr(colon + 1);
    char* end = nullptr;
    const long value = std::strtol(port.c_str(), &end, 10);
    if (port.empty() || *end != '\0' || value < 1 || value > 65535)
      return Error{"'" + url + "': the port must be a number 1..65535"};
    address.port = static_cast<std::uint16_t>(value);
  }
  return address;
}

double steadyMilliseconds() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct SpeculaClient::State {
  asio::io_context io;
  websocket::stream<beast::tcp_stream> ws{io};
  protocol::Encoding encoding = protocol::Encoding::Proto;
  beast::flat_buffer buffer;
  bool readPending = false, readDone = false;
  beast::error_code readError;
  std::optional<CloseInfo> closed;

  // Runs the io context until `done` or the timeout; returns whether it finished.
  template <class Done>
  bool runUntil(Done done, std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!done()) {
      io.restart();
      if (io.run_one_until(deadline) == 0 && std::chrono::steady_clock::now() >= deadline) return done();
    }
    return true;
  }
  void noteClosed(const beast::error_code& error) {
    if (closed) return;
    if (error == websocket::error::closed)
      closed = CloseInfo{ws.reason().code, std::string(ws.reason().reason.c_str())};
    else closed = CloseInfo{0, error.message()};
  }
};

SpeculaClient::SpeculaClient(std::unique_ptr<State> state) : state_(std::move(state)) {}
SpeculaClient::~SpeculaClient() { close(); }

Result<std::unique_ptr<SpeculaClient>> SpeculaClient::connect(const ServerAddress& address, protocol::Encoding encoding,
                                                              std::chrono::milliseconds timeout,
                                                              int receiveBufferBytes) {
  auto state = std::make_unique<State>();
  state->encoding = encoding;
  const std::string where = address.host + ":" + std::to_string(address.port);
  tcp::resolver resolver(state->io);
  beast::error_code error;
  const auto endpoints = resolver.resolve(address.host, std::to_string(address.port), error);
  if (error) return Error{"cannot resolve " + address.host + ": " + error.message()};
  // One endpoint at a time, so the socket's options are set before its SYN (the window follows the buffer).
  beast::tcp_stream& stream = beast::get_lowest_layer(state->ws);
  stream.expires_after(timeout);
  bool connected = false;
  error = asio::error::host_not_found;
  for (const auto& entry : endpoints) {
    const tcp::endpoint endpoint = entry.endpoint();
    connected = false;
    beast::error_code ignored;
    stream.socket().close(ignored);
    stream.socket().open(endpoint.protocol(), error);
    if (!error && receiveBufferBytes > 0)
      stream.socket().set_option(asio::socket_base::receive_buffer_size(receiveBufferBytes), error);
    if (error) break;
    stream.async_connect(endpoint, [&](beast::error_code e) {
      error = e;
      connected = true;
    });
    state->runUntil([&] { return connected; }, timeout + std::chrono::milliseconds(100));
    if (!connected || !error || error == beast::error::timeout) break;
  }
  if (!connected || error)
    return Error{"cannot connect to " + where + ": " + (connected ? error.message() : "timed out") +
                 " (is `specula serve` running there?)"};
  const std::string subprotocol(protocol::subprotocolName(encoding));
  state->ws.set_option(websocket::stream_base::decorator([subprotocol](websocket::request_type& request) {
    request.set(beast::http::field::sec_websocket_protocol, subprotocol);
  }));
  state->ws.read_message_max(64u << 20);  // frames can be large
  const std::string target = address.token.empty() ? "/ws" : "/ws?token=" + percentEncoded(address.token);
  websocket::response_type response;
  bool shaken = false;
  state->ws.async_handshake(response, where, target, [&](beast::error_code e) {
    error = e;
    shaken = true;
  });
  state->runUntil([&] { return shaken; }, timeout + std::chrono::milliseconds(100));
  if (!shaken) return Error{"WebSocket upgrade at " + where + " timed out"};
  if (error) {
    std::string why = error.message();
    if (response.result_int() != 0)
      why = "HTTP " + std::to_string(response.result_int()) + " " + std::string(response.reason());
    if (response.result_int() == 401) why += " (this server needs a token: add ?token=SECRET to the URL)";
    return Error{"the server at " + where + " refused the WebSocket upgrade: " + why};
  }
  beast::get_lowest_layer(state->ws).expires_never();
  state->ws.binary(encoding == protocol::Encoding::Proto);
  return std::unique_ptr<SpeculaClient>(new SpeculaClient(std::move(state)));
}

Status SpeculaClient::send(const v1::ClientMessage& message) {
  return sendRaw(protocol::encodeClientMessage(message, state_->encoding),
                 state_->encoding == protocol::Encoding::Json);
}

Status SpeculaClient::sendRaw(const std::string& payload, bool text) {
  if (state_->closed) return Error{"the connection is closed: " + state_->closed->reason};
  state_->ws.text(text);
  bool written = false;
  beast::error_code error;
  state_->ws.async_write(asio::buffer(payload), [&](beast::error_code e, std::size_t) {
    error = e;
    written = true;
  });
  if (!state_->runUntil([&] { return written; }, std::chrono::seconds(30)))
    return Error{"sending timed out: the server stopped reading"};
  if (error) {
    state_->noteClosed(error);
    return Error{"send failed: " + error.message()};
  }
  return {};
}

Result<v1::ServerMessage> SpeculaClient::receive(std::chrono::milliseconds timeout) {
  State& s = *state_;
  if (s.closed) return Error{"the connection is closed"};
  if (!s.readPending) {
    s.readPending = true;
    s.readDone = false;
    s.ws.async_read(s.buffer, [&s](beast::error_code e, std::size_t) {
      s.readError = e;
      s.readDone = true;
    });
  }
  if (!s.runUntil([&] { return s.readDone; }, timeout)) return Error{"timed out waiting for a message"};
  s.readPending = false;
  if (s.readError) {
    s.noteClosed(s.readError);
    return Error{"the server closed the connection: " + std::to_string(s.closed->code) + " " + s.closed->reason};
  }
  const auto data = s.buffer.cdata();
  auto message =
      protocol::decodeServerMessage(std::string_view(static_cast<const char*>(data.data()), data.size()), s.encoding);
  s.buffer.consume(s.buffer.size());
  return message;
}

std::optional<CloseInfo> SpeculaClient::closeInfo() const { return state_->closed; }

void SpeculaClient::close() {
  State& s = *state_;
  if (s.closed || !s.ws.is_open()) return;
  bool done = false;
  s.ws.async_close(websocket::close_code::normal, [&](beast::error_code) { done = true; });
  s.runUntil([&] { return done; }, std::chrono::seconds(2));
  s.closed = CloseInfo{1000, "closed by the client"};
  beast::error_code ignored;
  beast::get_lowest_layer(s.ws).socket().close(ignored);
  s.io.restart();
  s.io.poll();  // let cancelled handlers run while their captures are alive
}

void SpeculaClient::abort() {
  State& s = *state_;
  if (s.closed) return;
  s.closed = CloseInfo{0, "aborted by the client"};
  beast::error_code ignored;
  beast::get_lowest_layer(s.ws).socket().close(ignored);
  s.io.restart();
  s.io.poll();
}

}  // namespace specula::client
