#pragma once
// Bounded, confined file access for scene files and the assets they name: a hostile or mistaken path
// can neither exhaust memory nor reach outside the folder that holds the scene.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "base/Result.h"

namespace specula::scene {

inline constexpr std::size_t kMaxSceneFileBytes = std::size_t{64} << 20;   // scene JSON holds no geometry
inline constexpr std::size_t kMaxAssetFileBytes = std::size_t{256} << 20;  // one OBJ, glTF, GLB or .bin file

// The whole content of a regular file of at most `maxBytes` bytes. Fails with a message naming the file
// when it is missing, is not a regular file (a directory, a device, a pipe), is larger, or cannot be read.
Result<std::string> readBoundedFile(const std::filesystem::path& file, std::size_t maxBytes);

// `relative` (a path from a scene or asset file, '/'-separated) resolved against `folder`. Refuses empty
// and absolute paths, URI schemes, NUL bytes and paths that climb out of `folder` with "..".
Result<std::filesystem::path> resolveInside(const std::filesystem::path& folder, std::string_view relative);

// The file's extension in lower case (".glb"), and whether it names a glTF file (.gltf or .glb).
std::string lowercaseExtension(const std::filesystem::path& file);
bool isGltfFile(const std::filesystem::path& file);

// A third-party library's message (several lines, perhaps echoing raw input bytes) as one line of
// printable ASCII, safe to log or to put into a JSON reply.
std::string oneLine(std::string_view text);

}  // namespace specula::scene
