#pragma once
// Typed reads of glTF accessors, each checked first to lie wholly inside its buffer view and buffer.
#include <tiny_gltf.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <string>

#include "base/Result.h"

namespace specula::scene::gltf {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian");

std::size_t componentSize(int componentType);  // bytes per component of a TINYGLTF_COMPONENT_TYPE_*
std::size_t componentCount(int type);          // components per element of a TINYGLTF_TYPE_*

// An accessor whose every element has been checked to lie inside its buffer view and buffer.
struct Accessor {
  std::string name;  // "accessor 3 (NORMAL of primitive 0)", for messages
  const unsigned char* first = nullptr;
  std::size_t count = 0;
  std::size_t stride = 0;
  int componentType = 0;

  // Component c of element i as a float; integer components count as normalized.
  float component(std::size_t i, std::size_t c) const {
    const unsigned char* at = first + i * stride + c * componentSize(componentType);
    switch (componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return static_cast<float>(at[0]) / 255.0f;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return static_cast<float>(load<std::uint16_t>(at)) / 65535.0f;
      // Signed normalized, as the glTF spec maps them: the most negative value is -1 too.
      case TINYGLTF_COMPONENT_TYPE_BYTE: return std::max(static_cast<float>(load<std::int8_t>(at)) / 127.0f, -1.0f);
      case TINYGLTF_COMPONENT_TYPE_SHORT: return std::max(static_cast<float>(load<std::int16_t>(at)) / 32767.0f, -1.0f);
      default: return load<float>(at);
    }
  }

  // Component c of element i as an unnormalized integer (joint indices).
  std::uint32_t integer(std::size_t i, std::size_t c) const {
    const unsigned char* at = first + i * stride + c * componentSize(componentType);
    return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? at[0] : load<std::uint16_t>(at);
  }

  std::uint32_t index(std::size_t i) const {
    const unsigned char* at = first + i * stride;
    switch (componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return at[0];
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<std::uint16_t>(at);
      default: return load<std::uint32_t>(at);
    }
  }

  template <class T>
  static T load(const unsigned char* at) {
    T value;
    std::memcpy(&value, at, sizeof value);  // glTF only aligns within buffer views, not in memory
    return value;
  }
};

// Whether integer components of a vector must be normalized (attributes) or are plain integers (joints).
enum class IntegerComponents { Normalized, Indices };

// Accessor `index`, read as `role` (named in messages), once it has elements of `type` in one of
// `componentTypes`, at most `maxCount` of them, all inside its buffer; sparse accessors and, unless
// they are `Indices`, unnormalized integer vectors are refused.
Result<Accessor> checkedAccessor(const tinygltf::Model& model, int index, const std::string& role, int type,
                                 std::initializer_list<int> componentTypes, std::size_t maxCount,
                                 IntegerComponents integers = IntegerComponents::Normalized);

}  // namespace specula::scene::gltf
