#pragma once
// A request target ("/ws?token=...") split into what the routes read: its path and query values.
#include <string_view>

namespace specula::net {

// The target up to its query string.
std::string_view targetPath(std::string_view target);

// The value of `name` in the target's query string, still percent-encoded; empty when absent.
std::string_view queryValue(std::string_view target, std::string_view name);

}  // namespace specula::net
