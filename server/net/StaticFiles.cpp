#include "net/StaticFiles.h"

#include <fstream>
#include <iterator>
#include <algorithm>
#include <cctype>

namespace specula::net {

namespace {

constexpr std::uintmax_t kMaxFileBytes = 16u << 20;

bool safeSegment(std::string_view segment) {
  if (segment.empty() || segment.front() == '.') return false;  // no "..", no hidden files
  for (char c : segment)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-')) return false;
  return true;
}

std::string contentTypeOf(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".html") return "text/html; charset=utf-8";
  if (extension == ".js" || extension == ".mjs") return "text/javascript; charset=utf-8";
  if (extension == ".css") return "text/css; charset=utf-8";
  if (extension == ".json") return "application/json";
  if (extension == ".png") return "image/png";
  if (extension == ".svg") return "image/svg+xml";
  if (extension == ".proto" || extension == ".txt") return "text/plain; charset=utf-8";
  return "application/octet-stream";
}

}  // namespace

std::optional<StaticFile> StaticFiles::find(std::string_view requestPath) const {
  if (root_.empty() || requestPath.empty() || requestPath.front() != '/') return std::nullopt;
  std::string relative(requestPath.substr(1));
  if (relative.empty() || relative.back() == '/') relative += "index.html";
  std::filesystem::path path = root_;
  std::size_t start = 0;
  while (start <= relative.size()) {
    const std::size_t end = std::min(relative.find('/', start), relative.size());
    const std::string_view segment = std::string_view(relative).substr(start, end - start);
    if (!safeSegment(segment)) return std::nullopt;
    path /= std::string(segment);
    start = end + 1;
  }
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error) || std::filesystem::file_size(path, error) > kMaxFileBytes)
    return std::nullopt;
  std::ifstream file(path, std::ios::binary);
  if (!file) return std::nullopt;
  return StaticFile{std::string(std::istreambuf_iterator<char>(file), {}), contentTypeOf(path)};
}

}  // namespace specula::net
