#pragma once
// A read-only view of one value in a parsed JSON document that knows its JSONPath, so every complaint
// about the value says exactly where it is: "$.objects[2].material: unknown material ...".
#include <cstdint>
#include <glm/glm.hpp>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace specula::scene {

class JsonNode {
 public:
  // Thrown by fail() and by every getter whose value has the wrong shape. Readers catch it at their
  // public boundary and return it as an Error, so a deep schema reads straight down without checks.
  struct Failure {
    std::string message;  // "<path>: <problem>"
  };

  JsonNode(const nlohmann::json& value, std::string path);

  const std::string& path() const { return path_; }
  [[noreturn]] void fail(std::string_view problem) const;

  // Objects. expectObject() requires an object whose keys are all in `allowed` (listing them otherwise).
  void expectObject(std::initializer_list<std::string_view> allowed) const;
  std::optional<JsonNode> find(std::string_view key) const;  // fails when this is not an object
  JsonNode at(std::string_view key) const;                   // fails when the key is missing
  // The one key of `keys` present in this object; fails when none or several are.
  std::string_view oneOf(std::initializer_list<std::string_view> keys) const;

  // An object's keys and values (at most maxSize of them), in key order.
  std::vector<std::pair<std::string, JsonNode>> members(std::size_t maxSize) const;

  // An array with between minSize and maxSize elements.
  std::vector<JsonNode> array(std::size_t minSize, std::size_t maxSize) const;

  bool isString() const { return value_->is_string(); }
  bool isNumber() const { return value_->is_number(); }
  bool isArray() const { return value_->is_array(); }
  const std::string& string() const;
  bool boolean() const;
  double number() const;                          // finite, and within float range
  double positive() const;                        // number() > 0, also once rounded to float
  double atLeast(double low) const;               // number() >= low
  double inRange(double low, double high) const;  // number() in [low, high]
  std::int64_t integer(std::int64_t low, std::int64_t high) const;
  glm::vec2 vec2() const;  // [x, y]
  glm::vec3 vec3() const;  // [x, y, z]
  glm::vec4 vec4() const;  // [x, y, z, w]

  // The JSON name of this value's type ("object", "string", ...) for messages.
  std::string typeName() const;
  // `value` as JSON writes it ("0.5", "1e+20"), for messages.
  static std::string numberText(double value);
  // `text` as a JSON string literal, shortened to keep messages readable.
  static std::string quoted(std::string_view text);
  // The JSONPath step for an object key: ".name", or ["odd key"] when it is not an identifier.
  static std::string keyStep(std::string_view key);

 private:
  void readFloats(float* out, std::size_t count) const;

  const nlohmann::json* value_;
  std::string path_;
};

}  // namespace specula::scene
