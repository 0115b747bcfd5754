// Command encoders, compute passes and timestamp queries.
#include <algorithm>

#include "engine/gpu/vk_state.h"

namespace facet::gpu {
namespace detail {

CommandRecording::~CommandRecording() {
  if (commandBuffer) vkFreeCommandBuffers(device->device, device->commandPool, 1, &commandBuffer);
}

QuerySetState::~QuerySetState() {
  if (pool) vkDestroyQueryPool(device->device, pool, nullptr);
}

void CommandRecording::requireRecording(const char* operation) const {
  auto name = describe("command encoder", label);
  if (finished) throw Error(name + ": " + operation + " after finish()");
  if (passOpen)
    throw Error(name + ": " + operation + " while " + describe("compute pass", passLabel) + " is open; end() it first");
}

void CommandRecording::orderAccess(const std::vector<const BufferState*>& reads,
                                   const std::vector<const BufferState*>& writes) {
  bool hazard = false;
  for (const auto* b : reads) hazard |= writtenSinceBarrier.count(b) != 0;
  for (const auto* b : writes) hazard |= writtenSinceBarrier.count(b) != 0 || readSinceBarrier.count(b) != 0;
  if (hazard) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_UNIFORM_READ_BIT |
                            VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT |
                            VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
    vkCmdPipelineBarrier(
        commandBuffer, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
        VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0,
        1, &barrier, 0, nullptr, 0, nullptr);
    writtenSinceBarrier.clear();
    readSinceBarrier.clear();
  }
  readSinceBarrier.insert(reads.begin(), reads.end());
  writtenSinceBarrier.insert(writes.begin(), writes.end());
}

namespace {

void checkRange(const std::string& what, const Buffer& buffer, BufferUsage usage, std::uint64_t offset,
                std::uint64_t size) {
  auto name = what + " " + describe("buffer", require(buffer, what + " buffer").label);
  if (!has(buffer.usage(), usage))
    throw Error(name + ": needs usage " + toString(usage) + ", has " + toString(buffer.usage()));
  if (offset % 4 != 0 || size % 4 != 0) throw Error(name + ": offset and size must be multiples of 4 bytes");
  if (offset > buffer.size() || size > buffer.size() - offset)
    throw Error(name + ": range of " + std::to_string(size) + " bytes at offset " + std::to_string(offset) +
                " exceeds the size " + std::to_string(buffer.size()));
}

// Dispatch preconditions: a pipeline, every bind group it uses, ranges large
// enough for the shader's blocks. Returns the buffers read and written.
void prepareDispatch(CommandRecording& r, std::vector<const BufferState*>& reads,
                     std::vector<const BufferState*>& writes) {
  auto pass = describe("compute pass", r.passLabel);
  if (!r.pipeline) throw Error(pass + ": dispatch without setPipeline");
  const PipelineLayoutState& layout = *r.pipeline->layout;
  const auto& groups = layout.groups;
  const auto pipeline = describe("compute pipeline", r.pipeline->label);
  for (std::size_t i = 0; i < groups.size(); ++i) {
    if (i >= r.bindGroups.size() || !r.bindGroups[i])
      throw Error(pass + ": " + pipeline + " uses bind group " + std::to_string(i) + ", which is not set");
    // setBindGroup checked the group against the pipeline set then; a later
    // setPipeline may have switched to a layout the group was not made for.
    const BindGroupState& group = *r.bindGroups[i];
    if (!group.layout->matches(*groups[i]))
      throw Error(pass + ": " + describe("bind group", group.label) + " at group " + std::to_string(i) +
                  " was made for " + describe("bind group layout", group.layout->label) + ", which does not match " +
                  describe("bind group layout", groups[i]->label) + " of " + pipeline);
  }
  for (const auto& b : r.pipeline->shaderBindings) {
    const auto& bound = r.bindGroups[b.set]->buffers;
    auto it = std::find_if(bound.begin(), bound.end(), [&](const BoundBuffer& e) { return e.binding == b.binding; });
    const std::string where = "group " + std::to_string(b.set) + ", binding " + std::to_string(b.binding);
    const std::string block = b.name.empty() ? "" : " '" + b.name + "'";
    if (it == bound.end())
      throw Error(pass + ": " + describe("bind group", r.bindGroups[b.set]->label) + " has no buffer at " + where +
                  ", which the shader's block" + block + " of " + pipeline + " uses");
    if (it->size < b.minSize)
      throw Error(pass + ": " + describe("buffer", it->buffer->label) + " bound at " + where +
                  " is too small for the shader's block" + block + ": " + std::to_string(it->size) +
                  " bytes bound, at least " + std::to_string(b.minSize) + " needed");
  }
  // Vulkan keeps a set bound across vkCmdBindPipeline only while the pipeline
  // layouts are compatible up to that set; binding again with the current
  // layout is always right and costs little.
  for (std::uint32_t i = 0; i < groups.size(); ++i) {
    if (r.bindGroupPipelineLayouts[i] == layout.layout) continue;
    vkCmdBindDescriptorSets(r.commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE, layout.layout, i, 1, &r.bindGroups[i]->set,
                            0, nullptr);
    r.bindGroupPipelineLayouts[i] = layout.layout;
  }
  // A binding the layout lets the shader write is a read when the shader
  // declares it read-only: a storage texel buffer has no read-only type.
  const auto& shader = r.pipeline->shaderBindings;
  for (std::uint32_t i = 0; i < groups.size(); ++i) {
    for (const BoundBuffer& bound : r.bindGroups[i]->buffers) {
      auto b = std::find_if(shader.begin(), shader.end(),
                            [&](const spirv::Binding& s) { return s.set == i && s.binding == bound.binding; });
      bool written = bound.written && (b == shader.end() || b->written);
      (written ? writes : reads).push_back(bound.buffer.get());
    }
  }
}

}  // namespace
}  // namespace detail

// ---------------------------------------------------------------- encoder

CommandEncoder Device::createCommandEncoder(const CommandEncoderDescriptor& descriptor) {
  detail::require(*this, "device");
  auto state = std::make_shared<detail::CommandRecording>();
  state->device = state_;
  state->label = descriptor.label;
  state->commandBuffer = state_->beginCommandBuffer();
  return CommandEncoder(std::move(state));
}

ComputePassEncoder CommandEncoder::beginComputePass(const ComputePassDescriptor& descriptor) {
  detail::CommandRecording& r = detail::require(*this, "command encoder");
  r.requireRecording("beginComputePass");
  const auto& ts = descriptor.timestampWrites;
  if (ts.querySet) {
    detail::require(*ts.querySet, detail::describe("compute pass", descriptor.label) + " timestamp query set");
    const auto& set = ts.querySet->state();
    auto name = detail::describe("compute pass", descriptor.label) + " timestamps in " +
                detail::describe("query set", set->label);
    if (r.device->limits().timestampPeriodNs == 0) throw Error(name + ": the queue cannot write timestamps");
    if (ts.beginningOfPassWriteIndex >= set->count || ts.endOfPassWriteIndex >= set->count)
      throw Error(name + ": index past the query set's count " + std::to_string(set->count));
    if (ts.beginningOfPassWriteIndex == ts.endOfPassWriteIndex) throw Error(name + ": begin and end indices are equal");
    vkCmdResetQueryPool(r.commandBuffer, set->pool, ts.beginningOfPassWriteIndex, 1);
    vkCmdResetQueryPool(r.commandBuffer, set->pool, ts.endOfPassWriteIndex, 1);
    vkCmdWriteTimestamp(r.commandBuffer, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, set->pool, ts.beginningOfPassWriteIndex);
    r.timestampWrites.push_back({set, ts.beginningOfPassWriteIndex});
    r.timestampWrites.push_back({set, ts.endOfPassWriteIndex});
    r.passTimestamps = set;
    r.passEndTimestampIndex = ts.endOfPassWriteIndex;
    r.resources.push_back(set);
  }
  r.passOpen = true;
  ++r.passNumber;
  r.passLabel = descriptor.label;
  r.pipeline.reset();
  r.bindGroups.clear();
  r.bindGroupPipelineLayouts.clear();
  return ComputePassEncoder(state_, r.passNumber);
}

void CommandEncoder::copyBufferToBuffer(const Buffer& source, std::uint64_t sourceOffset, const Buffer& destination,
                                        std::uint64_t destinationOffset, std::uint64_t size) {
  detail::CommandRecording& r = detail::require(*this, "command encoder");
  r.requireRecording("copyBufferToBuffer");
  detail::checkRange("copyBufferToBuffer source", source, BufferUsage::CopySrc, sourceOffset, size);
  detail::checkRange("copyBufferToBuffer destination", destination, BufferUsage::CopyDst, destinationOffset, size);
  if (source.state() == destination.state() && sourceOffset < destinationOffset + size &&
      destinationOffset < sourceOffset + size)
    throw Error("copyBufferToBuffer within " + detail::describe("buffer", source.label()) + ": ranges overlap");
  if (size == 0) return;
  r.orderAccess({source.state().get()}, {destination.state().get()});
  VkBufferCopy region{sourceOffset, destinationOffset, size};
  vkCmdCopyBuffer(r.commandBuffer, source.state()->buffer, destination.state()->buffer, 1, &region);
  r.resources.push_back(source.state());
  r.resources.push_back(destination.state());
}

void CommandEncoder::clearBuffer(const Buffer& buffer, std::uint64_t offset, std::uint64_t size) {
  detail::CommandRecording& r = detail::require(*this, "command encoder");
  r.requireRecording("clearBuffer");
  detail::require(buffer, "clearBuffer buffer");
  if (offset > buffer.size())
    throw Error("clearBuffer " + detail::describe("buffer", buffer.label()) + ": offset past the end");
  if (size == kWholeSize) size = buffer.size() - offset;
  detail::checkRange("clearBuffer", buffer, BufferUsage::CopyDst, offset, size);
  if (size == 0) return;
  r.orderAccess({}, {buffer.state().get()});
  vkCmdFillBuffer(r.commandBuffer, buffer.state()->buffer, offset, size, 0);
  r.resources.push_back(buffer.state());
}

CommandBuffer CommandEncoder::finish() {
  detail::CommandRecording& r = detail::require(*this, "command encoder");
  r.requireRecording("finish");
  detail::endCommandBuffer(r.commandBuffer);
  r.finished = true;
  // The encoder keeps the recording so that later calls on it report
  // "after finish()" instead of finding nothing.
  return CommandBuffer(state_);
}

// ---------------------------------------------------------------- pass

ComputePassEncoder::ComputePassEncoder(std::shared_ptr<detail::CommandRecording> recording, std::uint64_t passNumber)
    : recording_(std::move(recording)), passNumber_(passNumber) {}

ComputePassEncoder::ComputePassEncoder(ComputePassEncoder&& other) noexcept
    : recording_(std::exchange(other.recording_, nullptr)), passNumber_(other.passNumber_) {}

ComputePassEncoder::~ComputePassEncoder() {
  if (recording_ && recording_->passOpen && recording_->passNumber == passNumber_) end();
}

namespace {
// The recording, if this pass is still the open one.
detail::CommandRecording& requirePass(const std::shared_ptr<detail::CommandRecording>& recording,
                                      std::uint64_t passNumber) {
  if (!recording) throw Error("compute pass encoder is moved-from or empty");
  if (!recording->passOpen || recording->passNumber != passNumber)
    throw Error("compute pass encoder used after its end()");
  return *recording;
}
}  // namespace

void ComputePassEncoder::setPipeline(const ComputePipeline& pipeline) {
  detail::CommandRecording& r = requirePass(recording_, passNumber_);
  detail::require(pipeline, detail::describe("compute pass", r.passLabel) + ": setPipeline's pipeline");
  r.pipeline = pipeline.state();
  vkCmdBindPipeline(r.commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE, r.pipeline->pipeline);
  r.resources.push_back(r.pipeline);
}

void ComputePassEncoder::setBindGroup(std::uint32_t index, const BindGroup& group) {
  detail::CommandRecording& r = requirePass(recording_, passNumber_);
  auto pass = detail::describe("compute pass", r.passLabel);
  detail::require(group, pass + ": setBindGroup(" + std::to_string(index) + ")'s bind group");
  if (!r.pipeline) throw Error(pass + ": setBindGroup(" + std::to_string(index) + ") before setPipeline");
  const auto& groups = r.pipeline->layout->groups;
  const auto& state = group.state();
  if (index >= groups.size())
    throw Error(pass + ": setBindGroup(" + std::to_string(index) +
                "): " + detail::describe("compute pipeline", r.pipeline->label) + " has " +
                std::to_string(groups.size()) + " bind group(s)");
  const auto& given = *state->layout;
  if (!given.matches(*groups[index]))
    throw Error(pass + ": " + detail::describe("bind group", state->label) + " was made for " +
                detail::describe("bind group layout", given.label) + ", which does not match group " +
                std::to_string(index) + " of " + detail::describe("compute pipeline", r.pipeline->label));
  if (r.bindGroups.size() <= index) {
    r.bindGroups.resize(index + 1);
    r.bindGroupPipelineLayouts.resize(index + 1, VK_NULL_HANDLE);
  }
  r.bindGroups[index] = state;
  r.bindGroupPipelineLayouts[index] = r.pipeline->layout->layout;
  vkCmdBindDescriptorSets(r.commandBuffer, VK_PIPELINE_BIND_POINT_COMPUTE, r.pipeline->layout->layout, index, 1,
                          &state->set, 0, nullptr);
  r.resources.push_back(state);
}

void ComputePassEncoder::dispatchWorkgroups(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  detail::CommandRecording& r = requirePass(recording_, passNumber_);
  std::vector<const detail::BufferState*> reads, writes;
  detail::prepareDispatch(r, reads, writes);
  const auto& max = r.device->limits().maxComputeWorkgroupsPerDimension;
  std::uint32_t counts[3] = {x, y, z};
  for (int i = 0; i < 3; ++i) {
    if (counts[i] > max[i])
      throw Error(detail::describe("compute pass", r.passLabel) + ": dispatchWorkgroups(" + std::to_string(x) + ", " +
                  std::to_string(y) + ", " + std::to_string(z) + ") exceeds maxComputeWorkgroupsPerDimension " +
                  std::to_string(max[i]) + " in " + "xyz"[i]);
  }
  if (x == 0 || y == 0 || z == 0) return;
  r.orderAccess(reads, writes);
  vkCmdDispatch(r.commandBuffer, x, y, z);
}

void ComputePassEncoder::dispatchWorkgroupsIndirect(const Buffer& indirect, std::uint64_t offset) {
  detail::CommandRecording& r = requirePass(recording_, passNumber_);
  detail::require(indirect, "dispatchWorkgroupsIndirect buffer");
  std::vector<const detail::BufferState*> reads, writes;
  detail::prepareDispatch(r, reads, writes);
  detail::checkRange("dispatchWorkgroupsIndirect", indirect, BufferUsage::Indirect, offset, 3 * sizeof(std::uint32_t));
  reads.push_back(indirect.state().get());
  r.orderAccess(reads, writes);
  vkCmdDispatchIndirect(r.commandBuffer, indirect.state()->buffer, offset);
  r.resources.push_back(indirect.state());
}

void ComputePassEncoder::end() {
  detail::CommandRecording& r = requirePass(recording_, passNumber_);
  if (r.passTimestamps) {
    vkCmdWriteTimestamp(r.commandBuffer, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, r.passTimestamps->pool,
                        r.passEndTimestampIndex);
    r.passTimestamps.reset();
  }
  r.passOpen = false;
  r.pipeline.reset();
  r.bindGroups.clear();
  r.bindGroupPipelineLayouts.clear();
}

// ---------------------------------------------------------------- queries

QuerySet Device::createQuerySet(const QuerySetDescriptor& descriptor) {
  detail::require(*this, "device");
  if (descriptor.count == 0) throw Error(detail::describe("query set", descriptor.label) + ": count must be positive");
  auto state = std::make_shared<detail::QuerySetState>();
  state->device = state_;
  state->label = descriptor.label;
  state->count = descriptor.count;
  state->submitted.assign(descriptor.count, false);
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = descriptor.count;
  detail::check(vkCreateQueryPool(state_->device, &info, nullptr, &state->pool), "vkCreateQueryPool");
  return QuerySet(std::move(state));
}

std::uint32_t QuerySet::count() const { return detail::require(*this, "query set").count; }

std::vector<double> QuerySet::readTimestampsNs(std::uint32_t first, std::uint32_t count) const {
  detail::require(*this, "query set");
  if (first + count > state_->count || first + count < first)
    throw Error(detail::describe("query set", state_->label) + ": reading [" + std::to_string(first) + ", " +
                std::to_string(first + count) + ") past its count " + std::to_string(state_->count));
  for (std::uint32_t i = first; i < first + count; ++i) {
    if (!state_->submitted[i])
      throw Error(detail::describe("query set", state_->label) + ": timestamp " + std::to_string(i) +
                  " was never written by submitted work");
  }
  std::vector<std::uint64_t> ticks(count);
  detail::check(
      vkGetQueryPoolResults(state_->device->device, state_->pool, first, count, ticks.size() * sizeof(std::uint64_t),
                            ticks.data(), sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
      "vkGetQueryPoolResults");
  std::vector<double> ns(count);
  for (std::uint32_t i = 0; i < count; ++i) ns[i] = double(ticks[i]) * state_->device->limits().timestampPeriodNs;
  return ns;
}

}  // namespace facet::gpu
