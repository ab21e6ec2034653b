#pragma once
// The command-line options every client shares: where the server is and which encoding to speak.
#include "ResumingClient.h"
#include "SpeculaClient.h"
#include "base/CommandLine.h"

namespace specula::client {

struct Connection {
  ServerAddress address;
  protocol::Encoding encoding = protocol::Encoding::Proto;
  ReconnectPolicy reconnect;
};

// --url, --encoding and --reconnect-attempts, for a tool's option table.
std::vector<OptionSpec> connectionOptions();
// Reads them, or says which is wrong and what it accepts.
Result<Connection> parseConnectionOptions(const CommandLine& options);
// "proto" or "json" (the --encoding values).
Result<protocol::Encoding> parseEncoding(const std::string& text);

}  // namespace specula::client
