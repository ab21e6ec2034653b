#pragma once
// A folder of this process's own under the system's temporary folder (mkdtemp: mode 0700), removed with its
// files when the owner is gone: for the resume secret and sockets of the serve processes a bench starts.
#include <filesystem>
#include <string_view>
#include <utility>

#include "base/Result.h"

namespace specula::app {

class PrivateFolder {
 public:
  PrivateFolder() = default;  // none: removes nothing
  // A new folder named `prefix` and six random characters.
  static Result<PrivateFolder> create(std::string_view prefix);
  PrivateFolder(PrivateFolder&& other) noexcept : path_(std::exchange(other.path_, {})) {}
  PrivateFolder& operator=(PrivateFolder&& other) noexcept;
  PrivateFolder(const PrivateFolder&) = delete;
  PrivateFolder& operator=(const PrivateFolder&) = delete;
  ~PrivateFolder();

  const std::filesystem::path& path() const { return path_; }
  // `name` in the folder, holding `secret` and readable by its owner only.
  std::filesystem::path writeSecret(std::string_view name, std::string_view secret) const;

 private:
  std::filesystem::path path_;
};

}  // namespace specula::app
