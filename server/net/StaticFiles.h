#pragma once
// Read-only files under one folder, served at the root of the site (the browser client).
#include <filesystem>
#include <optional>
#include <string>

namespace specula::net {

struct StaticFile {
  std::string body;
  std::string contentType;
};

class StaticFiles {
 public:
  explicit StaticFiles(std::filesystem::path root) : root_(std::move(root)) {}

  // The file for a request path ("/" is index.html), or nullopt when there is none or the path is not
  // a plain relative path of [A-Za-z0-9._-] segments (so nothing outside the folder can be named).
  std::optional<StaticFile> find(std::string_view requestPath) const;

 private:
  std::filesystem::path root_;
};

}  // namespace specula::net
