// White-box: a misuse planted below the API (straight into Vulkan) must reach
// the fixture's message list, or "no validation messages" would prove nothing.
#include "engine/gpu/vk_state.h"
#include "tests/support/gpu_device.h"

namespace facet::gpu::testing {
namespace {

TEST_F(GpuTest, AValidationMessageReachesTheFixture) {
  if (!instance_.validationEnabled()) GTEST_SKIP() << "the Khronos validation layer is not installed";
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 0;  // invalid: VUID-VkBufferCreateInfo-size-00912
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  vkCreateBuffer(device_.state()->device, &info, nullptr, &buffer);
  if (buffer) vkDestroyBuffer(device_.state()->device, buffer, nullptr);
  auto messages = instance_.takeValidationMessages();
  ASSERT_FALSE(messages.empty());
  EXPECT_THAT(messages.front(), ::testing::HasSubstr("size"));
}

}  // namespace
}  // namespace facet::gpu::testing
