#pragma once
// The names of one kind of scene entity ("mesh", "material", "object") in declaration order, so the scene
// loader can refuse duplicates and resolve references with messages that list what does exist.
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "scene/JsonNode.h"

namespace specula::scene {

class NameIndex {
 public:
  explicit NameIndex(std::string kind);

  // Registers the string at `name` as the next index and returns it; fails on an empty or overlong
  // name and on one already registered.
  std::string add(const JsonNode& name);
  // Registers `text`, a name made from the file (an included object's), failing at `where`.
  std::string add(std::string text, const JsonNode& where);

  // The index of the entity the string at `reference` names; fails listing the known names otherwise.
  std::uint32_t find(const JsonNode& reference) const;

 private:
  std::string kind_;
  std::vector<std::string> names_;
  std::vector<std::string> paths_;  // where each name was declared
  std::unordered_map<std::string, std::uint32_t> indices_;
};

}  // namespace specula::scene
