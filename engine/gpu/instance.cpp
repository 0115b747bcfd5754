// Instance, adapters and device creation.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>

#include "engine/gpu/vk_state.h"

namespace facet::gpu {
namespace detail {

const char* resultName(VkResult result) {
  switch (result) {
#define FACET_RESULT(name) \
  case name:               \
    return #name;
    FACET_RESULT(VK_SUCCESS)
    FACET_RESULT(VK_NOT_READY)
    FACET_RESULT(VK_TIMEOUT)
    FACET_RESULT(VK_INCOMPLETE)
    FACET_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
    FACET_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    FACET_RESULT(VK_ERROR_INITIALIZATION_FAILED)
    FACET_RESULT(VK_ERROR_DEVICE_LOST)
    FACET_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
    FACET_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
    FACET_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
    FACET_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
    FACET_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
    FACET_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
    FACET_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
    FACET_RESULT(VK_ERROR_FRAGMENTED_POOL)
    FACET_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
    FACET_RESULT(VK_ERROR_INVALID_SHADER_NV)
#undef FACET_RESULT
    default:
      return "VkResult(unknown)";
  }
}

void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) throw Error(std::string(what) + " failed: " + resultName(result));
}

InstanceState::~InstanceState() {
  if (messenger) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance, messenger, nullptr);
  }
  if (instance) vkDestroyInstance(instance, nullptr);
}

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* state = static_cast<InstanceState*>(user);
  std::string message = data && data->pMessage ? data->pMessage : "(no message)";
  std::fprintf(stderr, "facet: Vulkan validation: %s\n", message.c_str());
  std::lock_guard lock(state->messagesMutex);
  state->validationMessages.push_back(std::move(message));
  return VK_FALSE;
}

bool validationLayerInstalled() {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(),
                     [](const VkLayerProperties& l) { return std::strcmp(l.layerName, kValidationLayer) == 0; });
}

// The loader's own variables are named because they, not facet, can hide a
// driver that is installed.
std::string noDriverMessage(const std::string& what) {
  std::string message = "no Vulkan driver found (" + what +
                        "). Install Mesa's software driver with `apt-get install mesa-vulkan-drivers` "
                        "or a GPU vendor's driver";
  for (const char* var : {"VK_DRIVER_FILES", "VK_ICD_FILENAMES"}) {
    if (const char* value = std::getenv(var))
      message += std::string("; ") + var + "=" + value + " restricts the search";
  }
  return message;
}

constexpr EnumRow<AdapterType, VkPhysicalDeviceType> kAdapterTypes[] = {
    {AdapterType::DiscreteGpu, VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, "discrete GPU"},
    {AdapterType::IntegratedGpu, VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU, "integrated GPU"},
    {AdapterType::VirtualGpu, VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU, "virtual GPU"},
    {AdapterType::Cpu, VK_PHYSICAL_DEVICE_TYPE_CPU, "CPU"},
    {AdapterType::Other, VK_PHYSICAL_DEVICE_TYPE_OTHER, "other"},
};
static_assert(indexedByKey(kAdapterTypes));

AdapterType adapterType(VkPhysicalDeviceType type) {
  for (const auto& row : kAdapterTypes)
    if (row.vulkan == type) return row.key;
  return AdapterType::Other;
}

std::uint32_t computeQueueFamily(VkPhysicalDevice device, std::uint32_t* timestampBits = nullptr) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  for (std::uint32_t i = 0; i < count; ++i) {
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
      if (timestampBits) *timestampBits = families[i].timestampValidBits;
      return i;
    }
  }
  return UINT32_MAX;
}

void describeAdapter(VkPhysicalDevice device, AdapterInfo& info, Limits& limits) {
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES,
                                                      &driver};
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES, &maintenance3};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &subgroup};
  vkGetPhysicalDeviceProperties2(device, &properties);
  VkPhysicalDeviceFeatures features;
  vkGetPhysicalDeviceFeatures(device, &features);
  const VkPhysicalDeviceLimits& l = properties.properties.limits;

  info.name = properties.properties.deviceName;
  info.driver = driver.driverName;
  info.driverInfo = driver.driverInfo;
  std::uint32_t v = properties.properties.apiVersion;
  info.apiVersion = std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
                    std::to_string(VK_API_VERSION_PATCH(v));
  info.type = adapterType(properties.properties.deviceType);
  info.vendorId = properties.properties.vendorID;
  info.deviceId = properties.properties.deviceID;
  info.driverVersion = properties.properties.driverVersion;
  std::copy(std::begin(properties.properties.pipelineCacheUUID), std::end(properties.properties.pipelineCacheUUID),
            info.pipelineCacheUuid.begin());

  limits.maxBufferSize = maintenance3.maxMemoryAllocationSize;
  limits.maxStorageBufferBindingSize = l.maxStorageBufferRange;
  limits.maxUniformBufferBindingSize = l.maxUniformBufferRange;
  limits.minStorageBufferOffsetAlignment = std::uint32_t(l.minStorageBufferOffsetAlignment);
  limits.minUniformBufferOffsetAlignment = std::uint32_t(l.minUniformBufferOffsetAlignment);
  limits.maxBindGroups = l.maxBoundDescriptorSets;
  limits.maxStorageBuffersPerShaderStage = l.maxPerStageDescriptorStorageBuffers;
  for (int i = 0; i < 3; ++i) {
    limits.maxComputeWorkgroupsPerDimension[i] = l.maxComputeWorkGroupCount[i];
    limits.maxComputeWorkgroupSize[i] = l.maxComputeWorkGroupSize[i];
  }
  limits.maxComputeInvocationsPerWorkgroup = l.maxComputeWorkGroupInvocations;
  limits.maxComputeWorkgroupStorageSize = l.maxComputeSharedMemorySize;
  limits.subgroupSize = subgroup.subgroupSize;
  std::uint32_t timestampBits = 0;
  computeQueueFamily(device, &timestampBits);
  limits.timestampPeriodNs = timestampBits > 0 && l.timestampComputeAndGraphics ? l.timestampPeriod : 0.0;
  limits.shaderFloat64 = features.shaderFloat64;
  limits.maxTexelBufferElements = l.maxTexelBufferElements;
  limits.minTexelBufferOffsetAlignment = std::uint32_t(l.minTexelBufferOffsetAlignment);
}

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

}  // namespace
}  // namespace detail

const char* toString(AdapterType type) { return detail::kAdapterTypes[std::size_t(type)].name; }

Instance Instance::create(const InstanceDescriptor& descriptor) {
  using namespace detail;
  auto state = std::make_shared<InstanceState>();
  bool withValidation = descriptor.validation != Validation::Off && validationLayerInstalled();
  if (descriptor.validation == Validation::Required && !withValidation)
    throw Error(std::string("Vulkan validation was required but the layer ") + kValidationLayer +
                " is not installed (apt-get install vulkan-validationlayers)");

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "facet";
  app.apiVersion = VK_API_VERSION_1_2;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  const char* layer = kValidationLayer;
  const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
  messengerInfo.pfnUserCallback = onValidationMessage;
  messengerInfo.pUserData = state.get();
  if (withValidation) {
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = &extension;
    info.pNext = &messengerInfo;  // also catches messages from vkCreate/DestroyInstance
  }
  VkResult result = vkCreateInstance(&info, nullptr, &state->instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw Error(noDriverMessage("vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER"));
  check(result, "vkCreateInstance");

  if (withValidation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(state->instance, "vkCreateDebugUtilsMessengerEXT"));
    check(create ? create(state->instance, &messengerInfo, nullptr, &state->messenger) : VK_ERROR_EXTENSION_NOT_PRESENT,
          "vkCreateDebugUtilsMessengerEXT");
  }

  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(state->instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(state->instance, &count, devices.data()), "vkEnumeratePhysicalDevices");
  for (VkPhysicalDevice device : devices) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(device, &properties);
    // Timeline semaphores and the 1.2 feature structs are core from 1.2 on.
    if (properties.apiVersion < VK_API_VERSION_1_2 || computeQueueFamily(device) == UINT32_MAX) continue;
    state->physicalDevices.push_back(device);
    describeAdapter(device, state->infos.emplace_back(), state->limits.emplace_back());
  }
  if (state->physicalDevices.empty())
    throw Error(noDriverMessage("no Vulkan 1.2 device with a compute queue among " + std::to_string(count) + " found"));
  return Instance(std::move(state));
}

std::vector<AdapterInfo> Instance::enumerateAdapters() const { return detail::require(*this, "instance").infos; }

Adapter Instance::requestAdapter(const AdapterOptions& options) const {
  detail::require(*this, "instance");
  const std::string& wanted = options.name;
  const auto& infos = state_->infos;
  if (!wanted.empty()) {
    for (std::size_t i = 0; i < infos.size(); ++i) {
      if (detail::lowercase(infos[i].name).find(detail::lowercase(wanted)) != std::string::npos)
        return Adapter(state_, i);
    }
    std::string names;
    for (const auto& info : infos) names += "\n  " + info.name + " (" + toString(info.type) + ")";
    throw Error("no adapter name contains '" + wanted + "'; available:" + names);
  }
  std::size_t best = 0;
  for (std::size_t i = 1; i < infos.size(); ++i)
    if (infos[i].type < infos[best].type) best = i;  // declared in order of preference
  return Adapter(state_, best);
}

bool Instance::validationEnabled() const { return detail::require(*this, "instance").messenger != VK_NULL_HANDLE; }

std::vector<std::string> Instance::takeValidationMessages() const {
  std::lock_guard lock(detail::require(*this, "instance").messagesMutex);
  return std::exchange(state_->validationMessages, {});
}

Adapter::Adapter(std::shared_ptr<detail::InstanceState> instance, std::size_t index)
    : instance_(std::move(instance)), index_(index) {}

const AdapterInfo& Adapter::info() const { return instance_->infos[index_]; }
const Limits& Adapter::limits() const { return instance_->limits[index_]; }

Device Adapter::requestDevice(const DeviceDescriptor& descriptor) const {
  using namespace detail;
  auto state = std::make_shared<DeviceState>();
  state->instance = instance_;
  state->adapterIndex = index_;
  state->label = descriptor.label;
  state->physicalDevice = instance_->physicalDevices[index_];
  state->queueFamily = computeQueueFamily(state->physicalDevice);
  vkGetPhysicalDeviceMemoryProperties(state->physicalDevice, &state->memory);

  VkPhysicalDeviceVulkan12Features supported12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &supported12};
  vkGetPhysicalDeviceFeatures2(state->physicalDevice, &supported);
  if (!supported12.timelineSemaphore)
    throw Error(describe("adapter", info().name) + ": Vulkan timeline semaphores are required");

  // Features shaders may rely on, enabled when present: they cost nothing unused.
  VkPhysicalDeviceVulkan12Features enabled12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  enabled12.timelineSemaphore = VK_TRUE;
  enabled12.scalarBlockLayout = supported12.scalarBlockLayout;
  enabled12.hostQueryReset = supported12.hostQueryReset;
  VkPhysicalDeviceFeatures2 enabled{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &enabled12};
  enabled.features.shaderFloat64 = supported.features.shaderFloat64;
  enabled.features.shaderInt64 = supported.features.shaderInt64;

  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = state->queueFamily;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &enabled};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  check(vkCreateDevice(state->physicalDevice, &info, nullptr, &state->device), "vkCreateDevice");
  vkGetDeviceQueue(state->device, state->queueFamily, 0, &state->queue);

  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  poolInfo.queueFamilyIndex = state->queueFamily;
  check(vkCreateCommandPool(state->device, &poolInfo, nullptr, &state->commandPool), "vkCreateCommandPool");

  VkSemaphoreTypeCreateInfo timelineType{VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO};
  timelineType.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
  VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO, &timelineType};
  check(vkCreateSemaphore(state->device, &semaphoreInfo, nullptr, &state->timeline), "vkCreateSemaphore");

  VkPipelineCacheCreateInfo cacheInfo{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  cacheInfo.initialDataSize = descriptor.pipelineCache.size();
  cacheInfo.pInitialData = descriptor.pipelineCache.empty() ? nullptr : descriptor.pipelineCache.data();
  check(vkCreatePipelineCache(state->device, &cacheInfo, nullptr, &state->pipelineCache), "vkCreatePipelineCache");
  return Device(std::move(state));
}

}  // namespace facet::gpu
