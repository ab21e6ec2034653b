#include "ConnectionOptions.h"

namespace specula::client {

std::vector<OptionSpec> connectionOptions() {
  return {
      {"url", "URL", "server address; add ?token=SECRET when the server needs one", "ws://127.0.0.1:8080"},
      {"encoding", "proto|json", "WebSocket subprotocol: specula.v1.proto or specula.v1.json", "proto"},
      {"reconnect-attempts", "N",
       "when the connection is lost: tries (backoff 0.2 s doubling to 5 s) to reconnect and resume; 0 gives up at once",
       std::to_string(ReconnectPolicy{}.maxAttempts)},
  };
}

Result<protocol::Encoding> parseEncoding(const std::string& text) {
  if (text == "proto") return protocol::Encoding::Proto;
  if (text == "json") return protocol::Encoding::Json;
  return Error{"--encoding expects proto or json, got '" + text + "'"};
}

Result<Connection> parseConnectionOptions(const CommandLine& options) {
  auto address = parseServerUrl(options.text("url"));
  if (!address) return Error{address.error()};
  auto encoding = parseEncoding(options.text("encoding"));
  if (!encoding) return Error{encoding.error()};
  auto attempts = options.integer("reconnect-attempts", 0, 1000);
  if (!attempts) return Error{attempts.error()};
  ReconnectPolicy reconnect;
  reconnect.maxAttempts = *attempts;
  return Connection{*address, *encoding, reconnect};
}

}  // namespace specula::client
