#include "app/OutputFiles.h"

#include <fstream>

namespace specula::app {

namespace {
std::string unwritable(const std::string& path) {
  return "could not write '" + path + "': check the folder exists and is writable";
}
}  // namespace

Status checkWritable(const std::string& path) {
  if (!std::ofstream(path, std::ios::binary | std::ios::app)) return Error{unwritable(path)};
  return {};
}

Status writeFile(const std::string& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file << text;
  if (!file) return Error{unwritable(path)};
  return {};
}

}  // namespace specula::app
