#pragma once
// Percent-encoding of URL query values (the access token travels as ?token=...).
#include <string>
#include <string_view>

namespace specula {

// Every byte but the unreserved [A-Za-z0-9-_.~] as %XX.
std::string percentEncoded(std::string_view text);
// %XX escapes decoded; a broken escape stays as it is.
std::string percentDecoded(std::string_view text);

}  // namespace specula
