#include "app/PrivateFolder.h"

#include <stdlib.h>

#include <fstream>
#include <string>
#include <system_error>

namespace specula::app {

namespace fs = std::filesystem;

Result<PrivateFolder> PrivateFolder::create(std::string_view prefix) {
  std::string name = (fs::temp_directory_path() / (std::string(prefix) + "XXXXXX")).string();
  if (!mkdtemp(name.data())) return Error{"cannot create a folder under " + fs::temp_directory_path().string()};
  PrivateFolder folder;
  folder.path_ = name;
  return folder;
}

PrivateFolder& PrivateFolder::operator=(PrivateFolder&& other) noexcept {
  if (this != &other) {
    this->~PrivateFolder();
    path_ = std::exchange(other.path_, {});
  }
  return *this;
}

PrivateFolder::~PrivateFolder() {
  std::error_code ignored;
  if (!path_.empty()) fs::remove_all(path_, ignored);
}

fs::path PrivateFolder::writeSecret(std::string_view name, std::string_view secret) const {
  const fs::path file = path_ / name;
  std::ofstream(file) << secret;
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write);
  return file;
}

}  // namespace specula::app
