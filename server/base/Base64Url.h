#pragma once
// Base64 with the URL- and filename-safe alphabet (RFC 4648 §5), unpadded: tokens that travel in
// URLs, JSON and headers without escaping.
#include <optional>
#include <string>
#include <string_view>

namespace specula {

std::string base64UrlEncode(std::string_view bytes);
// The bytes, or nullopt for a character outside the alphabet, padding, or an impossible length.
std::optional<std::string> base64UrlDecode(std::string_view text);

}  // namespace specula
