#include "scene/NameIndex.h"

namespace specula::scene {

namespace {
constexpr std::size_t kMaxNameLength = 128;
constexpr std::size_t kNamesListed = 20;
}  // namespace

NameIndex::NameIndex(std::string kind) : kind_(std::move(kind)) {}

std::string NameIndex::add(const JsonNode& name) { return add(name.string(), name); }

std::string NameIndex::add(std::string text, const JsonNode& name) {
  if (text.empty() || text.size() > kMaxNameLength)
    name.fail(kind_ + " names must have 1 to " + std::to_string(kMaxNameLength) + " characters");
  const auto [it, added] = indices_.emplace(text, static_cast<std::uint32_t>(names_.size()));
  if (!added)
    name.fail("duplicate " + kind_ + " name " + JsonNode::quoted(text) + " (first declared at " + paths_[it->second] +
              ")");
  names_.push_back(std::move(text));
  paths_.push_back(name.path());
  return names_.back();
}

std::uint32_t NameIndex::find(const JsonNode& reference) const {
  const std::string& text = reference.string();
  if (const auto it = indices_.find(text); it != indices_.end()) return it->second;
  std::string known;
  for (std::size_t i = 0; i < names_.size() && i < kNamesListed; ++i)
    known += (i ? ", " : "") + JsonNode::quoted(names_[i]);
  if (names_.size() > kNamesListed) known += ", ... (" + std::to_string(names_.size()) + " in all)";
  reference.fail("unknown " + kind_ + " " + JsonNode::quoted(text) +
                 (names_.empty() ? " (none are declared)" : " (known: " + known + ")"));
}

}  // namespace specula::scene
