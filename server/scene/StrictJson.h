#pragma once
// JSON parsing that refuses what nlohmann accepts silently, duplicate keys (the last would win) and
// nesting deep enough to exhaust the stack of later recursive walks, and that names the JSONPath of
// numbers too large for a double (1e999).
#include <nlohmann/json.hpp>
#include <string_view>

#include "base/Result.h"

namespace specula::scene {

inline constexpr std::size_t kMaxJsonDepth = 64;

// The document, or a message (without a file name) giving the line and column of a syntax error or the
// JSONPath ("$.objects[2].name") of a duplicate key, a non-finite number or the container nested too deep.
Result<nlohmann::json> parseStrictJson(std::string_view text);

}  // namespace specula::scene
