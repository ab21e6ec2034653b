#include "scene/gltf/GltfAccessors.h"

#include <algorithm>

namespace specula::scene::gltf {

namespace {

std::string componentTypeName(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return std::to_string(componentType);
  }
}

std::string typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "type " + std::to_string(type);
  }
}

}  // namespace

std::size_t componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    default: return 4;
  }
}

std::size_t componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 4;
  }
}

Result<Accessor> checkedAccessor(const tinygltf::Model& model, int index, const std::string& role, int type,
                                 std::initializer_list<int> componentTypes, std::size_t maxCount,
                                 IntegerComponents integers) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
    return Error{role + " refers to accessor " + std::to_string(index) + ", but the file has " +
                 std::to_string(model.accessors.size())};
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  Accessor checked;
  checked.name = "accessor " + std::to_string(index) + " (" + role + ")";
  const std::string where = checked.name + ": ";
  if (accessor.sparse.isSparse) return Error{where + "sparse accessors are not supported"};
  if (accessor.type != type)
    return Error{where + "has " + typeName(accessor.type) + " elements, expected " + typeName(type)};
  if (std::find(componentTypes.begin(), componentTypes.end(), accessor.componentType) == componentTypes.end()) {
    std::string allowed;
    for (int t : componentTypes) allowed += (allowed.empty() ? "" : ", ") + componentTypeName(t);
    return Error{where + "component type " + componentTypeName(accessor.componentType) +
                 " is not allowed here (allowed: " + allowed + ")"};
  }
  if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && type != TINYGLTF_TYPE_SCALAR &&
      integers == IntegerComponents::Normalized && !accessor.normalized)
    return Error{where + "integer attributes must be normalized (KHR_mesh_quantization is not supported)"};
  if (accessor.count == 0) return Error{where + "is empty"};
  if (accessor.count > maxCount)
    return Error{where + "has " + std::to_string(accessor.count) + " elements, more than the limit of " +
                 std::to_string(maxCount)};
  if (accessor.bufferView < 0 || static_cast<std::size_t>(accessor.bufferView) >= model.bufferViews.size())
    return Error{where + "refers to buffer view " + std::to_string(accessor.bufferView) + ", but the file has " +
                 std::to_string(model.bufferViews.size()) + " (accessors without one are not supported)"};
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
  const std::string viewName = "buffer view " + std::to_string(accessor.bufferView);
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
    return Error{where + viewName + " refers to buffer " + std::to_string(view.buffer) + ", but the file has " +
                 std::to_string(model.buffers.size())};
  const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  if (view.byteLength > buffer.size() || view.byteOffset > buffer.size() - view.byteLength)
    return Error{where + viewName + " (" + std::to_string(view.byteLength) + " bytes at offset " +
                 std::to_string(view.byteOffset) + ") lies outside buffer " + std::to_string(view.buffer) + " (" +
                 std::to_string(buffer.size()) + " bytes)"};
  const std::size_t elementSize = componentSize(accessor.componentType) * componentCount(type);
  checked.stride = view.byteStride != 0 ? view.byteStride : elementSize;
  if (checked.stride < elementSize)
    return Error{where + viewName + " has a byte stride of " + std::to_string(checked.stride) + ", less than the " +
                 std::to_string(elementSize) + "-byte element"};
  // Written as subtractions and a division so that no hostile count, stride or offset can overflow.
  if (accessor.byteOffset > view.byteLength || elementSize > view.byteLength - accessor.byteOffset ||
      accessor.count - 1 > (view.byteLength - accessor.byteOffset - elementSize) / checked.stride)
    return Error{where + std::to_string(accessor.count) + " elements of " + std::to_string(elementSize) +
                 " bytes (stride " + std::to_string(checked.stride) + ", offset " +
                 std::to_string(accessor.byteOffset) + ") overrun " + viewName + " (" +
                 std::to_string(view.byteLength) + " bytes)"};
  checked.first = buffer.data() + view.byteOffset + accessor.byteOffset;
  checked.count = accessor.count;
  checked.componentType = accessor.componentType;
  return checked;
}

}  // namespace specula::scene::gltf
