#include "ScratchFolder.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace specula::fuzz {

namespace fs = std::filesystem;

ScratchFolder::ScratchFolder(std::initializer_list<Assets> assets) {
  std::string pattern = (fs::temp_directory_path() / "specula-fuzz-XXXXXX").string();
  if (!mkdtemp(pattern.data())) std::abort();
  path_ = pattern;
  for (const Assets& copy : assets) {
    const fs::path to = path_ / copy.to;
    fs::create_directories(to);
    for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(SPECULA_TEST_DATA_DIR) / copy.from))
      if (entry.is_regular_file()) fs::copy_file(entry.path(), to / entry.path().filename());
  }
}

ScratchFolder::~ScratchFolder() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

fs::path ScratchFolder::write(std::string_view name, const std::uint8_t* bytes, std::size_t size) const {
  fs::path file = path_ / name;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes), static_cast<std::streamsize>(size));
  if (!out.flush()) std::abort();
  return file;
}

}  // namespace specula::fuzz
