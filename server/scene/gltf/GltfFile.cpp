#include "scene/gltf/GltfFile.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "scene/AssetFiles.h"
#include "scene/StrictJson.h"

namespace specula::scene::gltf {

namespace {

namespace fs = std::filesystem;

static_assert(std::endian::native == std::endian::little, "GLB headers are little-endian");

constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

std::uint32_t readU32(std::string_view bytes, std::size_t offset) {
  std::uint32_t value;
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  return value;
}

// The GLB's JSON chunk once the framing checks out; tinygltf 2.7 lets the BIN chunk run 8 bytes past the end.
Result<std::string_view> glbJsonChunk(std::string_view bytes) {
  const std::size_t size = bytes.size();
  if (size < 20) return Error{"truncated GLB: " + std::to_string(size) + " bytes, fewer than the 20-byte header"};
  if (const std::uint32_t version = readU32(bytes, 4); version != 2)
    return Error{"GLB container version " + std::to_string(version) + "; only glTF 2.0 is supported"};
  if (const std::uint32_t length = readU32(bytes, 8); length != size)
    return Error{"GLB header declares " + std::to_string(length) + " bytes but the file has " + std::to_string(size) +
                 " (truncated?)"};
  const std::uint64_t jsonLength = readU32(bytes, 12);
  if (readU32(bytes, 16) != kChunkJson) return Error{"the first GLB chunk is not the JSON chunk"};
  const std::uint64_t binStart = 20 + jsonLength;
  if (binStart > size) return Error{"the GLB JSON chunk runs past the end of the file"};
  if (binStart < size) {
    if (binStart + 8 > size) return Error{"the GLB BIN chunk header is truncated"};
    if (readU32(bytes, binStart + 4) != kChunkBin) return Error{"the second GLB chunk is not the BIN chunk"};
    if (binStart + 8 + readU32(bytes, binStart) > size) return Error{"the GLB BIN chunk runs past the end of the file"};
  }
  return bytes.substr(20, jsonLength);
}

// tinygltf copies the BIN chunk for every buffer without a URI, so declared sizes, not the file, bound its memory.
std::optional<std::string> bufferSizeProblem(const nlohmann::json& gltf) {
  if (!gltf.is_object() || !gltf.contains("buffers") || !gltf["buffers"].is_array()) return std::nullopt;
  std::uint64_t total = 0;
  for (std::size_t i = 0; i < gltf["buffers"].size(); ++i) {
    const nlohmann::json& buffer = gltf["buffers"][i];
    const std::string where = "buffer " + std::to_string(i) + ": ";
    if (!buffer.is_object() || !buffer.contains("byteLength") || !buffer["byteLength"].is_number_unsigned())
      return where + "byteLength must be a positive integer";
    const std::uint64_t length = buffer["byteLength"].get<std::uint64_t>();
    if (length > kMaxAssetFileBytes || (total += length) > kMaxAssetFileBytes)
      return where + "buffers declare more than " + std::to_string(kMaxAssetFileBytes) + " bytes in all";
  }
  return std::nullopt;
}

// What tinygltf's file callbacks may read: files inside the folder, within one budget (URIs may repeat a file).
struct AssetFolder {
  fs::path folder;
  std::size_t bytesLeft = kMaxAssetFileBytes;
  std::string refusal;  // why a path was refused, to explain tinygltf's "file not found"
};

bool fileExists(const std::string& path, void* user) {
  auto& assets = *static_cast<AssetFolder*>(user);
  Result<fs::path> resolved = resolveInside(assets.folder, path);
  if (!resolved) {
    if (assets.refusal.empty()) assets.refusal = resolved.error();  // tinygltf retries with "./" prefixed
    return false;
  }
  std::error_code ec;
  return fs::exists(resolved.value(), ec);
}

std::string expandFilePath(const std::string& path, void*) { return path; }

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  auto& assets = *static_cast<AssetFolder*>(user);
  Result<fs::path> resolved = resolveInside(assets.folder, path);
  Result<std::string> bytes = resolved ? readBoundedFile(resolved.value(), assets.bytesLeft) : Error{resolved.error()};
  if (!bytes) {
    *err = bytes.error();
    return false;
  }
  assets.bytesLeft -= bytes->size();
  out->assign(bytes->begin(), bytes->end());
  return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err = "the importer never writes files";
  return false;
}

}  // namespace

Result<tinygltf::Model> loadModel(std::string_view bytes, const fs::path& folder, DecodedImages& images) {
  if (bytes.empty()) return Error{"empty file; expected glTF JSON or a GLB container"};
  const bool binary = bytes.starts_with("glTF");
  Result<std::string_view> json = binary ? glbJsonChunk(bytes) : Result<std::string_view>(bytes);
  if (!json) return Error{json.error()};
  // Parsed strictly first: tinygltf walks "extras" recursively, so nesting depth must be bounded before it runs.
  Result<nlohmann::json> document = parseStrictJson(json.value());
  if (!document) return Error{document.error()};
  if (auto problem = bufferSizeProblem(document.value())) return Error{*problem};

  AssetFolder assets{folder, kMaxAssetFileBytes, {}};
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&decodeImage, &images);
  loader.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, &refuseWrite, &assets});
  tinygltf::Model model;
  std::string error, warning;
  try {
    // An empty base folder makes tinygltf hand URIs to the callbacks unchanged; they resolve them in `folder`.
    const auto size = static_cast<unsigned int>(binary ? bytes.size() : json->size());
    const bool loaded =
        binary ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                             reinterpret_cast<const unsigned char*>(bytes.data()), size, "")
               : loader.LoadASCIIFromString(&model, &error, &warning, json->data(), size, "");
    if (!loaded)
      return Error{"not a valid glTF 2.0 asset: " + oneLine(error) +
                   (assets.refusal.empty() ? "" : " (" + assets.refusal + ")")};
  } catch (const std::exception& e) {
    return Error{"cannot be parsed: " + std::string(e.what())};
  }
  images.unread = assets.refusal.empty() ? oneLine(warning) : assets.refusal;
  return model;
}

}  // namespace specula::scene::gltf
