// An HTTP request as the server reads it (Beast's parser with the server's header limit), then its target
// as the routes read it: the path, the static file it names, and the percent-decoded access token.
// GCC 12 with ASan at -O2 takes Beast's optional content length in basic_parser for uninitialized (a
// false positive, reported at the header's line), which -Werror would make fatal.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/beast/http.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "base/UrlEncoding.h"
#include "net/RequestTarget.h"
#include "net/StaticFiles.h"

namespace http = boost::beast::http;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const specula::net::StaticFiles files(SPECULA_TEST_DATA_DIR "/web");
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  if (specula::percentDecoded(specula::percentEncoded(bytes)) != bytes) std::abort();

  http::request_parser<http::empty_body> parser;
  parser.header_limit(8 * 1024);  // as HttpConnection
  parser.eager(true);
  boost::beast::error_code error;
  parser.put(boost::asio::buffer(data, size), error);
  if (error || !parser.is_header_done()) return 0;
  const auto target = parser.get().target();
  const std::string_view request(target.data(), target.size());
  (void)files.find(specula::net::targetPath(request));
  (void)specula::percentDecoded(specula::net::queryValue(request, "token"));
  return 0;
}
