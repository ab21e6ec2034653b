#include "scene/JsonNode.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace specula::scene {

namespace {

std::string keyList(std::initializer_list<std::string_view> keys) {
  std::string list;
  for (std::string_view key : keys) list += (list.empty() ? "" : ", ") + JsonNode::quoted(key);
  return list;
}

}  // namespace

JsonNode::JsonNode(const nlohmann::json& value, std::string path) : value_(&value), path_(std::move(path)) {}

void JsonNode::fail(std::string_view problem) const { throw Failure{path_ + ": " + std::string(problem)}; }

void JsonNode::expectObject(std::initializer_list<std::string_view> allowed) const {
  if (!value_->is_object()) fail("expected an object, got " + typeName());
  for (const auto& [key, value] : value_->items())
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      JsonNode(value, path_ + keyStep(key)).fail("unknown key; allowed keys here: " + keyList(allowed));
}

std::optional<JsonNode> JsonNode::find(std::string_view key) const {
  if (!value_->is_object()) fail("expected an object, got " + typeName());
  const auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  return JsonNode(*it, path_ + keyStep(key));
}

JsonNode JsonNode::at(std::string_view key) const {
  std::optional<JsonNode> node = find(key);
  if (!node) fail("missing required key " + quoted(key));
  return *std::move(node);
}

std::string_view JsonNode::oneOf(std::initializer_list<std::string_view> keys) const {
  std::optional<std::string_view> chosen;
  for (std::string_view key : keys) {
    if (!find(key)) continue;
    if (chosen) fail("has both " + quoted(*chosen) + " and " + quoted(key) + "; give exactly one of " + keyList(keys));
    chosen = key;
  }
  if (!chosen) fail("needs exactly one of " + keyList(keys));
  return *chosen;
}

std::vector<std::pair<std::string, JsonNode>> JsonNode::members(std::size_t maxSize) const {
  if (!value_->is_object()) fail("expected an object, got " + typeName());
  if (value_->size() > maxSize)
    fail("object has " + std::to_string(value_->size()) + " keys; expected at most " + std::to_string(maxSize));
  std::vector<std::pair<std::string, JsonNode>> out;
  for (auto it = value_->begin(); it != value_->end(); ++it)
    out.emplace_back(it.key(), JsonNode(it.value(), path_ + keyStep(it.key())));
  return out;
}

std::vector<JsonNode> JsonNode::array(std::size_t minSize, std::size_t maxSize) const {
  if (!value_->is_array()) fail("expected an array, got " + typeName());
  if (value_->size() < minSize || value_->size() > maxSize)
    fail("array has " + std::to_string(value_->size()) + " elements; expected " +
         (minSize == maxSize ? std::to_string(minSize)
                             : "between " + std::to_string(minSize) + " and " + std::to_string(maxSize)));
  std::vector<JsonNode> elements;
  elements.reserve(value_->size());
  for (std::size_t i = 0; i < value_->size(); ++i)
    elements.emplace_back((*value_)[i], path_ + "[" + std::to_string(i) + "]");
  return elements;
}

const std::string& JsonNode::string() const {
  if (!value_->is_string()) fail("expected a string, got " + typeName());
  return value_->get_ref<const std::string&>();
}

bool JsonNode::boolean() const {
  if (!value_->is_boolean()) fail("expected true or false, got " + typeName());
  return value_->get<bool>();
}

double JsonNode::number() const {
  if (!value_->is_number()) fail("expected a number, got " + typeName());
  const double value = value_->get<double>();
  // Values end up in floats; anything beyond float range would silently become infinity.
  if (!(std::abs(value) <= std::numeric_limits<float>::max())) fail("number " + numberText(value) + " is out of range");
  return value;
}

double JsonNode::positive() const {
  const double value = number();
  if (!(static_cast<float>(value) > 0.0f)) fail("must be greater than 0, got " + numberText(value));
  return value;
}

double JsonNode::atLeast(double low) const {
  const double value = number();
  if (!(value >= low)) fail("must be at least " + numberText(low) + ", got " + numberText(value));
  return value;
}

double JsonNode::inRange(double low, double high) const {
  const double value = number();
  if (!(value >= low && value <= high))
    fail("must lie in [" + numberText(low) + ", " + numberText(high) + "], got " + numberText(value));
  return value;
}

std::int64_t JsonNode::integer(std::int64_t low, std::int64_t high) const {
  if (!value_->is_number_integer()) fail("expected an integer, got " + (isNumber() ? value_->dump() : typeName()));
  // Unsigned values may exceed int64; compare them before converting.
  const bool inside = value_->is_number_unsigned()
                          ? high >= 0 && value_->get<std::uint64_t>() <= static_cast<std::uint64_t>(high) &&
                                static_cast<std::int64_t>(value_->get<std::uint64_t>()) >= low
                          : value_->get<std::int64_t>() >= low && value_->get<std::int64_t>() <= high;
  if (!inside)
    fail("must be an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "], got " + value_->dump());
  return value_->get<std::int64_t>();
}

void JsonNode::readFloats(float* out, std::size_t count) const {
  if (!value_->is_array() || value_->size() != count)
    fail("expected an array of " + std::to_string(count) + " numbers, got " +
         (value_->is_array() ? "an array of " + std::to_string(value_->size()) : typeName()));
  std::size_t i = 0;
  for (const JsonNode& element : array(count, count)) out[i++] = static_cast<float>(element.number());
}

glm::vec2 JsonNode::vec2() const {
  glm::vec2 v;
  readFloats(&v.x, 2);
  return v;
}

glm::vec3 JsonNode::vec3() const {
  glm::vec3 v;
  readFloats(&v.x, 3);
  return v;
}

glm::vec4 JsonNode::vec4() const {
  glm::vec4 v;
  readFloats(&v.x, 4);
  return v;
}

std::string JsonNode::numberText(double value) { return nlohmann::json(value).dump(); }

std::string JsonNode::typeName() const { return value_->type_name(); }

std::string JsonNode::quoted(std::string_view text) {
  constexpr std::size_t kShown = 80;
  const std::string shown(text.substr(0, kShown));
  return nlohmann::json(shown).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) +
         (text.size() > kShown ? "..." : "");
}

std::string JsonNode::keyStep(std::string_view key) {
  const bool identifier = !key.empty() && !std::isdigit(static_cast<unsigned char>(key.front())) &&
                          std::all_of(key.begin(), key.end(),
                                      [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
  return identifier ? "." + std::string(key) : "[" + quoted(key) + "]";
}

}  // namespace specula::scene
