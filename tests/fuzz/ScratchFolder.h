#pragma once
// A folder of its own for one fuzzing process: the file-based loaders read their input from a file in
// it, and the asset files that inputs may name are copied in beside it.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string_view>

namespace specula::fuzz {

class ScratchFolder {
 public:
  // Files to copy in: those (not folders) of `from`, a folder under tests/data, into `to`, one in the scratch folder.
  struct Assets {
    std::string_view from, to;
  };

  // A new folder under the system's temporary folder, holding `assets`.
  explicit ScratchFolder(std::initializer_list<Assets> assets = {});
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // `name` in the folder, holding exactly `bytes`.
  std::filesystem::path write(std::string_view name, const std::uint8_t* bytes, std::size_t size) const;

 private:
  std::filesystem::path path_;
};

}  // namespace specula::fuzz
