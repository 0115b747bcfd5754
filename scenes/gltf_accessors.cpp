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

// An accessor without a buffer view is zeros the file does not hold: a bound
// on them keeps a few bytes of JSON from claiming gigabytes.
constexpr std::size_t kMaxZeroElements = std::size_t(1) << 24;

}  // namespace

std::size_t GltfReader::components(int accessorIndex, const std::string& where) const {
  if (accessorIndex < 0 || std::size_t(accessorIndex) >= model_.accessors.size())
    fail(where, "accessor index out of range");
  return std::size_t(
      tinygltf::GetNumComponentsInType(std::uint32_t(model_.accessors[std::size_t(accessorIndex)].type)));
}

std::vector<double> GltfReader::read(int accessorIndex, const std::string& where, const ElementFormat& format) const {
  const std::size_t components = this->components(accessorIndex, where);
  const tinygltf::Accessor& a = model_.accessors[std::size_t(accessorIndex)];
  const std::string accessor = "accessors[" + std::to_string(accessorIndex) + "]";
  if (components != format.components || std::find(format.componentTypes.begin(), format.componentTypes.end(),
                                                   a.componentType) == format.componentTypes.end())
    fail(where, accessor + " must be " + format.name + ", is componentType " + std::to_string(a.componentType) +
                    " with " + std::to_string(components) + " components");
  if (format.normalizedOnly && !a.normalized && a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    fail(where, accessor + " must be " + format.name + ", is componentType " + std::to_string(a.componentType) +
                    " without normalized: true");
  const std::size_t componentBytes = std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType)));
  const std::size_t elementBytes = components * componentBytes;
  double range = 1.0;
  if (format.normalizable && a.normalized && a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) range = 255;
  if (format.normalizable && a.normalized && a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) range = 65535;
  const auto value = [&](const unsigned char* element, std::size_t c) {
    return component(element + c * componentBytes, a.componentType) / range;
  };
  // glTF 2.0, 3.6.2.3: an accessor without a buffer view is zeros, which its
  // sparse substitution may then replace.
  if (a.bufferView < 0 && !a.sparse.isSparse) fail(where, accessor + " has neither a buffer view nor sparse values");
  if (a.bufferView < 0 && a.count > kMaxZeroElements)
    fail(where, accessor + " has no buffer view, and such an accessor may have at most " +
                    std::to_string(kMaxZeroElements) + " elements, has " + std::to_string(a.count));
  std::vector<double> out;
  if (a.bufferView >= 0) {
    const auto [begin, stride] = elements(a.bufferView, a.byteOffset, a.count, elementBytes, where, accessor);
    out.resize(a.count * components);
    for (std::size_t i = 0; i < a.count; ++i)
      for (std::size_t c = 0; c < components; ++c) out[i * components + c] = value(begin + i * stride, c);
  } else {
    out.assign(a.count * components, 0.0);
  }
  if (!a.sparse.isSparse) return out;
  const std::string sparse = accessor + ".sparse";
  const int indexType = a.sparse.indices.componentType;
  if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    fail(where, sparse + ".indices: componentType must be 5121, 5123 or 5125, is " + std::to_string(indexType));
  if (a.sparse.count < 1 || std::size_t(a.sparse.count) > a.count)
    fail(where, sparse + ".count must be in [1, the accessor's count], is " + std::to_string(a.sparse.count));
  const std::size_t count = std::size_t(a.sparse.count);
  const std::size_t indexBytes = std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(indexType)));
  const auto indices = elements(a.sparse.indices.bufferView, std::size_t(std::max(a.sparse.indices.byteOffset, 0)),
                                count, indexBytes, where, sparse + ".indices");
  const auto values = elements(a.sparse.values.bufferView, std::size_t(std::max(a.sparse.values.byteOffset, 0)), count,
                               elementBytes, where, sparse + ".values");
  for (std::size_t k = 0; k < count; ++k) {
    const double index = component(indices.first + k * indexBytes, indexType);
    if (index >= double(a.count))
      fail(where, sparse + ".indices: index " + std::to_string(std::size_t(index)) + " is past the accessor's count");
    for (std::size_t c = 0; c < components; ++c)
      out[std::size_t(index) * components + c] = value(values.first + k * elementBytes, c);
  }
  return out;
}

std::pair<const unsigned char*, std::size_t> GltfReader::elements(int viewIndex, std::size_t byteOffset,
                                                                  std::size_t count, std::size_t elementBytes,
                                                                  const std::string& where,
                                                                  const std::string& accessor) const {
  if (viewIndex < 0 || std::size_t(viewIndex) >= model_.bufferViews.size())
    fail(where, accessor + ": buffer view index " + std::to_string(viewIndex) + " out of range");
  const tinygltf::BufferView& view = model_.bufferViews[std::size_t(viewIndex)];
  if (view.buffer < 0 || std::size_t(view.buffer) >= model_.buffers.size()) fail(where, "buffer index out of range");
  const std::vector<unsigned char>& data = model_.buffers[std::size_t(view.buffer)].data;
  const std::size_t stride = view.byteStride ? view.byteStride : elementBytes;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset ||
      !elementsFit(byteOffset, count, stride, elementBytes, view.byteLength))
    fail(where, accessor + " (count " + std::to_string(count) + ", byteOffset " + std::to_string(byteOffset) +
                    ", stride " + std::to_string(stride) + ") reads past the end of its buffer");
  return {data.data() + view.byteOffset + byteOffset, stride};
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
