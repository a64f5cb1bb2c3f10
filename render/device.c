/* device.c - instance, validation messenger, physical device choice, the
 * logical device with its single queue, and the serialised submit path. */
#include "render_vk.h"

#include "log.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RND_VALIDATION_LAYER "VK_LAYER_KHRONOS_validation"

static VKAPI_ATTR VkBool32 VKAPI_CALL debug_callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                     VkDebugUtilsMessageTypeFlagsEXT types,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void* user)
{
    rnd_context* ctx = user;
    bool error = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0;
    atomic_fetch_add(&ctx->validation_messages, 1u);
    tv_log(error ? TV_LOG_ERROR : TV_LOG_WARN, "vulkan validation: %s", data->pMessage);
    return VK_FALSE;
}

static bool want_validation(const rnd_desc* desc)
{
    if (desc->validation != 0)
        return desc->validation > 0;
    const char* env = getenv("TRIMVR_VALIDATION");
    return env && strcmp(env, "1") == 0;
}

static bool layer_present(const char* name)
{
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, NULL);
    VkLayerProperties* layers = calloc(count ? count : 1, sizeof *layers);
    if (!layers)
        return false;
    vkEnumerateInstanceLayerProperties(&count, layers);
    bool found = false;
    for (uint32_t i = 0; i < count && !found; i++)
        found = strcmp(layers[i].layerName, name) == 0;
    free(layers);
    return found;
}

static VkDebugUtilsMessengerCreateInfoEXT messenger_info(rnd_context* ctx)
{
    return (VkDebugUtilsMessengerCreateInfoEXT){
        .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
        .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
        .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT,
        .pfnUserCallback = debug_callback,
        .pUserData = ctx,
    };
}

static bool create_instance(rnd_context* ctx, const rnd_desc* desc, bool validation, char* err, size_t err_size)
{
    uint32_t api = 0;
    vkEnumerateInstanceVersion(&api);
    if (api < VK_API_VERSION_1_3) {
        snprintf(err, err_size, "Vulkan loader supports %u.%u, trimvr needs 1.3", VK_API_VERSION_MAJOR(api),
                 VK_API_VERSION_MINOR(api));
        return false;
    }
    if (validation && !layer_present(RND_VALIDATION_LAYER)) {
        snprintf(err, err_size, "validation requested but %s is not installed", RND_VALIDATION_LAYER);
        return false;
    }
    const char* layer = RND_VALIDATION_LAYER;
    const char* extensions[17];
    uint32_t extension_count = 0;
    if (desc->instance_extension_count > 16) {
        snprintf(err, err_size, "%u instance extensions requested, at most 16 supported", desc->instance_extension_count);
        return false;
    }
    for (uint32_t i = 0; i < desc->instance_extension_count; i++)
        extensions[extension_count++] = desc->instance_extensions[i];
    if (validation)
        extensions[extension_count++] = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkDebugUtilsMessengerCreateInfoEXT messenger = messenger_info(ctx);
    VkInstanceCreateInfo info = {
        .sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
        /* chained so instance creation and destruction are validated too */
        .pNext = validation ? &messenger : NULL,
        .pApplicationInfo = &(VkApplicationInfo){.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                                                 .pApplicationName = "trimvr",
                                                 .apiVersion = VK_API_VERSION_1_3},
        .enabledLayerCount = validation ? 1 : 0,
        .ppEnabledLayerNames = &layer,
        .enabledExtensionCount = extension_count,
        .ppEnabledExtensionNames = extensions,
    };
    if (!RND_VK_OK(vkCreateInstance(&info, NULL, &ctx->instance), err, err_size))
        return false;
    if (!validation)
        return true;
    PFN_vkCreateDebugUtilsMessengerEXT create =
        (PFN_vkCreateDebugUtilsMessengerEXT)vkGetInstanceProcAddr(ctx->instance, "vkCreateDebugUtilsMessengerEXT");
    if (!create) {
        snprintf(err, err_size, "vkCreateDebugUtilsMessengerEXT not available with validation on");
        return false;
    }
    return RND_VK_OK(create(ctx->instance, &messenger, NULL, &ctx->messenger), err, err_size);
}

static int type_rank(VkPhysicalDeviceType type)
{
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 2;
    default: return 3;
    }
}

static bool is_index(const char* s)
{
    if (!*s)
        return false;
    for (; *s; s++)
        if (!isdigit((unsigned char)*s))
            return false;
    return true;
}

static bool choose_physical_device(rnd_context* ctx, const char* wanted, char* err, size_t err_size)
{
    uint32_t count = 0;
    if (!RND_VK_OK(vkEnumeratePhysicalDevices(ctx->instance, &count, NULL), err, err_size))
        return false;
    if (count == 0) {
        snprintf(err, err_size, "no Vulkan physical device found");
        return false;
    }
    VkPhysicalDevice* devices = calloc(count, sizeof *devices);
    if (!devices) {
        snprintf(err, err_size, "out of memory listing physical devices");
        return false;
    }
    vkEnumeratePhysicalDevices(ctx->instance, &count, devices);
    int best = -1, best_rank = 4;
    for (uint32_t i = 0; i < count; i++) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(devices[i], &p);
        if (wanted) {
            bool match = is_index(wanted) ? strtoul(wanted, NULL, 10) == i : strstr(p.deviceName, wanted) != NULL;
            if (match) {
                best = (int)i;
                break;
            }
        } else if (type_rank(p.deviceType) < best_rank) {
            best = (int)i;
            best_rank = type_rank(p.deviceType);
        }
    }
    if (best < 0) {
        snprintf(err, err_size, "no Vulkan device matches \"%s\" (%u devices)", wanted, count);
    } else {
        ctx->physical = devices[best];
        vkGetPhysicalDeviceProperties(ctx->physical, &ctx->props);
        vkGetPhysicalDeviceMemoryProperties(ctx->physical, &ctx->memory);
    }
    free(devices);
    return best >= 0;
}

/* Features the mesh pass and the PVS passes rely on; a missing one fails
 * device creation with its name rather than a validation error later.
 * Descriptor indexing is deliberately not among them: lavapipe lacks it
 * (textures are array layers instead, see gpu_scene.c). */
static bool check_features(rnd_context* ctx, char* err, size_t err_size)
{
    if (ctx->props.apiVersion < VK_API_VERSION_1_3) {
        snprintf(err, err_size, "%s supports Vulkan %u.%u, trimvr needs 1.3", ctx->props.deviceName,
                 VK_API_VERSION_MAJOR(ctx->props.apiVersion), VK_API_VERSION_MINOR(ctx->props.apiVersion));
        return false;
    }
    VkPhysicalDeviceVulkan12Features f12 = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan13Features f13 = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
                                            .pNext = &f12};
    VkPhysicalDeviceFeatures2 f = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &f13};
    vkGetPhysicalDeviceFeatures2(ctx->physical, &f);
    const char* missing = !f13.dynamicRendering ? "dynamicRendering"
                          : !f13.synchronization2 ? "synchronization2"
                          : !f.features.fragmentStoresAndAtomics ? "fragmentStoresAndAtomics"
                          : !f.features.independentBlend         ? "independentBlend"
                                                                 : NULL;
    if (missing) {
        snprintf(err, err_size, "%s lacks the Vulkan feature %s", ctx->props.deviceName, missing);
        return false;
    }
    /* Optional: only P2's front-patch slots use them; without, the PVS runs its no-int64 variant (front-patch rule
     * off, larger but conservative). TRIMVR_NO_INT64=1 leaves them off on any device, to test that variant. */
    const char* off = getenv("TRIMVR_NO_INT64");
    ctx->int64_atomics = f.features.shaderInt64 && f12.shaderBufferInt64Atomics && !(off && strcmp(off, "1") == 0);
    return true;
}

static bool create_device(rnd_context* ctx, bool swapchain, char* err, size_t err_size)
{
    uint32_t family_count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx->physical, &family_count, NULL);
    VkQueueFamilyProperties families[16];
    if (family_count > 16)
        family_count = 16;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx->physical, &family_count, families);
    const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    uint32_t family = UINT32_MAX;
    for (uint32_t i = 0; i < family_count && family == UINT32_MAX; i++)
        if ((families[i].queueFlags & need) == need)
            family = i;
    if (family == UINT32_MAX) {
        snprintf(err, err_size, "%s has no graphics+compute queue family", ctx->props.deviceName);
        return false;
    }
    ctx->queue_family = family;
    const uint32_t bits = families[family].timestampValidBits;
    ctx->timestamps = bits > 0 && ctx->props.limits.timestampPeriod > 0.0f;
    ctx->timestamp_mask = bits >= 64 ? UINT64_MAX : (UINT64_C(1) << bits) - 1;

    VkPhysicalDeviceVulkan12Features f12 = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                            .shaderBufferInt64Atomics = ctx->int64_atomics};
    VkPhysicalDeviceVulkan13Features f13 = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
                                            .pNext = &f12,
                                            .dynamicRendering = VK_TRUE,
                                            .synchronization2 = VK_TRUE};
    VkPhysicalDeviceFeatures2 features = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                          .pNext = &f13,
                                          .features = {.fragmentStoresAndAtomics = VK_TRUE,
                                                       .independentBlend = VK_TRUE,
                                                       .shaderInt64 = ctx->int64_atomics}};
    float priority = 1.0f;
    VkDeviceCreateInfo info = {
        .sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
        .pNext = &features,
        .queueCreateInfoCount = 1,
        .pQueueCreateInfos = &(VkDeviceQueueCreateInfo){.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                                        .queueFamilyIndex = family,
                                                        .queueCount = 1,
                                                        .pQueuePriorities = &priority},
        .enabledExtensionCount = swapchain ? 1 : 0,
        .ppEnabledExtensionNames = (const char* const[]){VK_KHR_SWAPCHAIN_EXTENSION_NAME},
    };
    if (!RND_VK_OK(vkCreateDevice(ctx->physical, &info, NULL, &ctx->device), err, err_size))
        return false;
    vkGetDeviceQueue(ctx->device, family, 0, &ctx->queue);
    return true;
}

rnd_context* rnd_create(const rnd_desc* desc_in, char* err, size_t err_size)
{
    rnd_desc desc = desc_in ? *desc_in : (rnd_desc){0};
    if (!desc.device) {
        const char* env = getenv("TRIMVR_DEVICE");
        desc.device = env && *env ? env : NULL;
    }
    rnd_context* ctx = calloc(1, sizeof *ctx);
    if (!ctx) {
        snprintf(err, err_size, "out of memory creating the render context");
        return NULL;
    }
    atomic_init(&ctx->validation_messages, 0u);
    pthread_mutex_init(&ctx->queue_mutex, NULL);
    bool validation = want_validation(&desc);
    if (!create_instance(ctx, &desc, validation, err, err_size) ||
        !choose_physical_device(ctx, desc.device, err, err_size) || !check_features(ctx, err, err_size) ||
        !create_device(ctx, desc.swapchain, err, err_size) ||
        !rnd_mesh_pipeline_create(ctx, err, err_size)) {
        rnd_destroy(ctx);
        return NULL;
    }
    const VkPhysicalDeviceLimits* l = &ctx->props.limits;
    tv_log(TV_LOG_INFO, "vulkan device: %s (api %u.%u.%u, validation %s, maxStorageBufferRange %u MiB, timestamps %s)",
           ctx->props.deviceName, VK_API_VERSION_MAJOR(ctx->props.apiVersion),
           VK_API_VERSION_MINOR(ctx->props.apiVersion), VK_API_VERSION_PATCH(ctx->props.apiVersion),
           validation ? "on" : "off", l->maxStorageBufferRange >> 20, ctx->timestamps ? "yes" : "no");
    return ctx;
}

void rnd_destroy(rnd_context* ctx)
{
    if (!ctx)
        return;
    if (ctx->device) {
        vkDeviceWaitIdle(ctx->device);
        rnd_mesh_pipeline_destroy(ctx);
        vkDestroyDevice(ctx->device, NULL);
    }
    if (ctx->messenger) {
        PFN_vkDestroyDebugUtilsMessengerEXT destroy = (PFN_vkDestroyDebugUtilsMessengerEXT)vkGetInstanceProcAddr(
            ctx->instance, "vkDestroyDebugUtilsMessengerEXT");
        destroy(ctx->instance, ctx->messenger, NULL);
    }
    if (ctx->instance)
        vkDestroyInstance(ctx->instance, NULL);
    pthread_mutex_destroy(&ctx->queue_mutex);
    free(ctx);
}

uint32_t rnd_validation_message_count(const rnd_context* ctx)
{
    return atomic_load(&((rnd_context*)ctx)->validation_messages);
}

const char* rnd_device_name(const rnd_context* ctx) { return ctx->props.deviceName; }

bool rnd_submit(rnd_context* ctx, VkCommandBuffer cmd, VkFence fence, char* err, size_t err_size)
{
    VkSubmitInfo info = {.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd};
    pthread_mutex_lock(&ctx->queue_mutex);
    VkResult r = vkQueueSubmit(ctx->queue, 1, &info, fence);
    pthread_mutex_unlock(&ctx->queue_mutex);
    return rnd_vk_ok(r, "vkQueueSubmit", err, err_size);
}
