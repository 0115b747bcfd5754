// glTF accessors read into doubles, each checked against its element format
// and the bounds of its buffer.
#include <algorithm>
#include <cstdint>
#include <cstring>

#include "scenes/gltf_internal.h"

namespace facet::scene::detail {
namespace {

// Whether `count` elements of `elementBytes`, `stride` apart from byte
// `begin`, end by byte `end`, in arithmetic that cannot wrap around.
bool elementsFit(std::size_t begin, std::size_t count, std::size_t stride, std::size_t elementBytes, std::size_t end) {
  if (count == 0) return true;
  if (begin > end || elementBytes > end - begin) return false;
  return count - 1 <= (end - begin - elementBytes) / stride;
}

}  // namespace

std::vector<double> GltfReader::read(int accessorIndex, const std::string& where, const ElementFormat& format) const {
  if (accessorIndex < 0 || std::size_t(accessorIndex) >= model_.accessors.size())
    fail(where, "accessor index out of range");
  const tinygltf::Accessor& a = model_.accessors[std::size_t(accessorIndex)];
  const std::string accessor = "accessors[" + std::to_string(accessorIndex) + "]";
  const std::size_t components = std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(a.type)));
  if (components != format.components || std::find(format.componentTypes.begin(), format.componentTypes.end(),
                                                   a.componentType) == format.componentTypes.end())
    fail(where, accessor + " must be " + format.name + ", is componentType " + std::to_string(a.componentType) +
                    " with " + std::to_string(components) + " components");
  if (a.sparse.isSparse) fail(where, accessor + " is sparse, and sparse accessors are not read");
  if (a.bufferView < 0 || std::size_t(a.bufferView) >= model_.bufferViews.size())
    fail(where, "accessor has no buffer view (sparse accessors are not supported)");
  const tinygltf::BufferView& view = model_.bufferViews[std::size_t(a.bufferView)];
  if (view.buffer < 0 || std::size_t(view.buffer) >= model_.buffers.size()) fail(where, "buffer index out of range");
  const std::vector<unsigned char>& data = model_.buffers[std::size_t(view.buffer)].data;
  const std::size_t componentBytes = std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType)));
  const std::size_t elementBytes = components * componentBytes;
  const std::size_t stride = view.byteStride ? view.byteStride : elementBytes;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset ||
      !elementsFit(a.byteOffset, a.count, stride, elementBytes, view.byteLength))
    fail(where, accessor + " (count " + std::to_string(a.count) + ", byteOffset " + std::to_string(a.byteOffset) +
                    ", stride " + std::to_string(stride) + ") reads past the end of its buffer");
  const unsigned char* begin = data.data() + view.byteOffset + a.byteOffset;
  double range = 1.0;
  if (format.normalizable && a.normalized && a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) range = 255;
  if (format.normalizable && a.normalized && a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) range = 65535;
  std::vector<double> out;
  out.reserve(a.count * components);
  for (std::size_t i = 0; i < a.count; ++i) {
    const unsigned char* element = begin + i * stride;
    for (std::size_t c = 0; c < components; ++c)
      out.push_back(component(element + c * componentBytes, a.componentType) / range);
  }
  return out;
}

double GltfReader::component(const unsigned char* p, int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

}  // namespace facet::scene::detail
