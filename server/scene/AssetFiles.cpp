#include "scene/AssetFiles.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>

namespace specula::scene {

namespace fs = std::filesystem;

std::string lowercaseExtension(const fs::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
  return extension;
}

bool isGltfFile(const fs::path& file) {
  const std::string extension = lowercaseExtension(file);
  return extension == ".gltf" || extension == ".glb";
}

Result<std::string> readBoundedFile(const fs::path& file, std::size_t maxBytes) {
  const std::string name = file.string();
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (status.type() == fs::file_type::not_found) return Error{name + ": no such file"};
  if (ec) return Error{name + ": cannot be inspected (" + ec.message() + ")"};
  if (status.type() == fs::file_type::directory) return Error{name + ": is a directory, not a file"};
  if (status.type() != fs::file_type::regular) return Error{name + ": is not a regular file"};
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec) return Error{name + ": cannot be inspected (" + ec.message() + ")"};
  if (size > maxBytes)
    return Error{name + ": " + std::to_string(size) + " bytes, more than the limit of " + std::to_string(maxBytes)};

  std::ifstream in(file, std::ios::binary);
  if (!in) return Error{name + ": cannot be opened (" + std::strerror(errno) + ")"};
  std::string content(static_cast<std::size_t>(size), '\0');
  in.read(content.data(), static_cast<std::streamsize>(content.size()));
  if (static_cast<std::uintmax_t>(in.gcount()) != size) return Error{name + ": changed or failed while being read"};
  return content;
}

Result<fs::path> resolveInside(const fs::path& folder, std::string_view relative) {
  const std::string base = folder.empty() ? std::string(".") : folder.string();
  const std::string shown = "\"" + oneLine(relative.substr(0, 200)) + "\"";
  if (relative.empty()) return Error{"empty file path"};
  if (relative.find('\0') != std::string_view::npos) return Error{"file path contains a NUL byte"};
  if (relative.find("://") != std::string_view::npos)
    return Error{"file path " + shown + " is a URI; only paths relative to " + base + " are allowed"};
  const fs::path path{std::string(relative)};
  if (path.has_root_path()) return Error{"file path " + shown + " is absolute; give it relative to " + base};
  const fs::path normal = path.lexically_normal();
  if (!normal.empty() && *normal.begin() == "..")
    return Error{"file path " + shown + " climbs out of " + base + "; keep assets in that folder or below it"};
  return folder / normal;
}

std::string oneLine(std::string_view text) {
  std::string line;
  for (char c : text) {
    if (c == '\n' || c == '\r') {
      if (!line.empty() && line.back() != ' ') line += "; ";
    } else {
      line += c == '\t' ? ' ' : c >= ' ' && c <= '~' ? c : '?';
    }
  }
  while (!line.empty() && (line.back() == ' ' || line.back() == ';')) line.pop_back();
  constexpr std::size_t kMaxLength = 400;  // libraries repeat themselves; the first problems tell the story
  return line.size() > kMaxLength ? line.substr(0, kMaxLength) + "..." : line;
}

}  // namespace specula::scene
