// Building the Reflection from a parsed spirv::Module: the bindings with their
// block sizes, the specialization constants and the workgroup size.
#include "engine/gpu/spirv_module.h"

namespace facet::gpu::spirv {

Reflection Module::reflection() const {
  Reflection r;
  r.computeEntryPoints = entryPoints_;
  r.workgroupSize = workgroupSize_;
  if (builtinWorkgroupSize_) {
    const auto& components = constant(*builtinWorkgroupSize_, "the WorkgroupSize built-in").operands;
    for (int i = 0; i < 3 && std::size_t(i) < components.size(); ++i) resolveWorkgroupDimension(components[i], r, i);
  }
  for (const auto& [id, c] : constants_) {
    auto deco = decorations_.find(id);
    if (deco == decorations_.end() || !deco->second.has(SpecId)) continue;
    r.specConstants.push_back(specConstant(id, c, deco->second.literal(SpecId)));
  }
  for (const auto& [id, var] : variables_) reflectVariable(id, var, r);
  return r;
}

SpecConstant Module::specConstant(std::uint32_t id, const Type& c, std::uint32_t specId) const {
  SpecConstant s;
  s.id = specId;
  auto name = names_.find(id);
  s.name = name != names_.end() ? name->second : "";
  s.defaultValue = scalarValue(id, "specialization constant");
  if (c.op == OpSpecConstantTrue || c.op == OpSpecConstantFalse) {
    s.kind = ScalarKind::Bool;
    return s;
  }
  const Type& t = scalarType(id, "specialization constant");
  s.width = t.op == OpTypeBool ? 32 : t.operands[0];
  s.kind = t.op == OpTypeFloat  ? ScalarKind::Float
           : t.op == OpTypeBool ? ScalarKind::Bool
           : t.operands[1]      ? ScalarKind::Int
                                : ScalarKind::UInt;
  return s;
}

void Module::resolveWorkgroupDimension(std::uint32_t constantId, Reflection& r, int dim) const {
  r.workgroupSize[dim] = std::uint32_t(scalarValue(constantId, "workgroup size component"));
  auto deco = decorations_.find(constantId);
  if (deco != decorations_.end() && deco->second.has(SpecId))
    r.workgroupSizeSpecIds[dim] = deco->second.literal(SpecId);
}

bool Module::allMembersNonWritable(std::uint32_t structId) const {
  const Type& t = type(structId, "block type");
  auto members = memberDecorations_.find(structId);
  if (members == memberDecorations_.end()) return false;
  for (std::uint32_t m = 0; m < t.operands.size(); ++m) {
    auto d = members->second.find(m);
    if (d == members->second.end() || !d->second.has(NonWritable)) return false;
  }
  return true;
}

// A texel buffer is an image of Dim Buffer, sampled (Sampled 1, possibly
// wrapped in a sampled image type) or storage (Sampled 2), whose four
// 32-bit components are the texel format.
void Module::reflectTexelBuffer(std::uint32_t typeId, const std::string& binding, bool nonWritable, Binding& b) const {
  auto find = [&](std::uint32_t id) {
    auto it = types_.find(id);
    return it == types_.end() ? nullptr : &it->second;
  };
  const Type* image = find(typeId);
  if (image && image->op == OpTypeSampledImage) image = find(image->operands[0]);
  if (!image || image->op != OpTypeImage || image->operands[1] != DimBuffer ||
      (image->operands[5] != 1 && image->operands[5] != 2))
    fail(binding +
         " is an image, a sampler or an array of them: facet::gpu supports only uniform, storage and texel "
         "buffers, one per binding");
  const bool storage = image->operands[5] == 2;
  const Type& component = type(image->operands[0], "image component type");
  const bool isFloat = component.op == OpTypeFloat;
  if ((!isFloat && component.op != OpTypeInt) || component.operands[0] != 32)
    fail(binding + " does not have 32-bit components: facet::gpu supports only 4 x 32-bit texel formats");
  const bool isSigned = !isFloat && component.operands[1] == 1;
  const std::uint32_t format = isFloat ? ImageFormatRgba32f : isSigned ? ImageFormatRgba32i : ImageFormatRgba32ui;
  if (storage && image->operands[6] != format)
    fail(binding + " has image format " + std::to_string(image->operands[6]) +
         ": facet::gpu supports only 4 x 32-bit texel formats (rgba32f, rgba32ui, rgba32i, as the component type)");
  b.type = storage ? BindingType::StorageTexelBuffer : BindingType::TexelBuffer;
  b.texelFormat = isFloat ? TexelFormat::Rgba32Float : isSigned ? TexelFormat::Rgba32Sint : TexelFormat::Rgba32Uint;
  b.written = storage && !nonWritable;
  b.minSize = kTexelBytes;
}

void Module::reflectVariable(std::uint32_t id, const Type& var, Reflection& r) const {
  std::uint32_t storageClass = var.operands[1];
  if (storageClass == StorageClassPushConstant) r.usesPushConstants = true;
  auto deco = decorations_.find(id);
  if (deco == decorations_.end() || !deco->second.has(BindingDecoration)) return;
  if (storageClass != StorageClassUniformConstant && storageClass != StorageClassUniform &&
      storageClass != StorageClassStorageBuffer)
    return;
  auto name = names_.find(id);
  Binding b;
  b.set = deco->second.has(DescriptorSet) ? deco->second.literal(DescriptorSet) : 0;
  b.binding = deco->second.literal(BindingDecoration);
  b.name = name != names_.end() ? name->second : "";
  const std::string binding = "binding (group " + std::to_string(b.set) + ", binding " + std::to_string(b.binding) +
                              (b.name.empty() ? "" : ", '" + b.name + "'") + ")";
  const Type& pointer = type(var.operands[0], "variable type");
  if (pointer.op != OpTypePointer) fail(binding + " does not have a pointer type");
  std::uint32_t blockType = pointer.operands[1];
  if (storageClass == StorageClassUniformConstant) {
    reflectTexelBuffer(blockType, binding, deco->second.has(NonWritable), b);
    r.bindings.push_back(b);
    return;
  }
  const Type& block = type(blockType, "block type");
  if (block.op == OpTypeArray || block.op == OpTypeRuntimeArray)
    fail(binding + " is an array of blocks: facet::gpu supports one buffer per binding; give each its own binding");
  if (block.op != OpTypeStruct) fail(binding + " is not a block (struct) type");
  bool bufferBlock = decorations_.count(blockType) && decorations_.at(blockType).has(BufferBlock);
  bool storage = storageClass == StorageClassStorageBuffer || bufferBlock;
  bool readOnly = deco->second.has(NonWritable) || allMembersNonWritable(blockType);
  b.type = !storage ? BindingType::Uniform : readOnly ? BindingType::ReadOnlyStorage : BindingType::Storage;
  b.written = b.type == BindingType::Storage;
  b.minSize = sizeOf(blockType);
  if (b.name.empty() && names_.count(blockType)) b.name = names_.at(blockType);
  r.bindings.push_back(b);
}

const SpecConstant* Reflection::findConstant(const std::string& key) const {
  for (const auto& c : specConstants)
    if (c.name == key || std::to_string(c.id) == key) return &c;
  return nullptr;
}

Reflection reflect(std::span<const std::uint32_t> words, const std::string& label) {
  return Module(words, label).reflection();
}

}  // namespace facet::gpu::spirv
