#include "vk_check.h"

#include "log.h"

#include <stdio.h>
#include <string.h>

const char* rnd_vk_result_name(VkResult result)
{
    switch (result) {
#define RND_RESULT_CASE(name) case name: return #name;
        RND_RESULT_CASE(VK_SUCCESS)
        RND_RESULT_CASE(VK_NOT_READY)
        RND_RESULT_CASE(VK_TIMEOUT)
        RND_RESULT_CASE(VK_EVENT_SET)
        RND_RESULT_CASE(VK_EVENT_RESET)
        RND_RESULT_CASE(VK_INCOMPLETE)
        RND_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        RND_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        RND_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
        RND_RESULT_CASE(VK_ERROR_DEVICE_LOST)
        RND_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        RND_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        RND_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        RND_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        RND_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
        RND_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        RND_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        RND_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL)
        RND_RESULT_CASE(VK_ERROR_UNKNOWN)
        RND_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        RND_RESULT_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        RND_RESULT_CASE(VK_ERROR_FRAGMENTATION)
        RND_RESULT_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        RND_RESULT_CASE(VK_ERROR_SURFACE_LOST_KHR)
        RND_RESULT_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
        RND_RESULT_CASE(VK_SUBOPTIMAL_KHR)
        RND_RESULT_CASE(VK_ERROR_OUT_OF_DATE_KHR)
#undef RND_RESULT_CASE
    default: {
        static _Thread_local char unknown[32];
        snprintf(unknown, sizeof unknown, "VkResult(%d)", (int)result);
        return unknown;
    }
    }
}

bool rnd_vk_ok(VkResult result, const char* call_text, char* err, size_t err_size)
{
    if (result == VK_SUCCESS)
        return true;
    size_t name_len = strcspn(call_text, "(");
    if (err && err_size) {
        snprintf(err, err_size, "%.*s: %s", (int)name_len, call_text, rnd_vk_result_name(result));
    } else {
        tv_log(TV_LOG_ERROR, "%.*s: %s", (int)name_len, call_text, rnd_vk_result_name(result));
    }
    return false;
}
