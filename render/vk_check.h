/* vk_check.h - VkResult checks that name the failing call.
 *
 * Every Vulkan call whose result matters goes through RND_VK_OK so a failure
 * reads "vkCreateBuffer: VK_ERROR_OUT_OF_DEVICE_MEMORY" instead of a bare
 * number. Calls with legitimate non-success results (fence/query polling) are
 * checked by hand at their call site. */
#ifndef TRIMVR_RENDER_VK_CHECK_H
#define TRIMVR_RENDER_VK_CHECK_H

#include <stdbool.h>
#include <stddef.h>
#include <vulkan/vulkan.h>

/* The enumerant's name ("VK_ERROR_DEVICE_LOST"), or "VkResult(<n>)" for an
 * unknown value (returned in a static buffer: only for immediate logging). */
const char* rnd_vk_result_name(VkResult result);

/* Returns true when result is VK_SUCCESS. Otherwise writes
 * "<call name>: <VkResult name>" into err (call_text is the stringified call,
 * cut at its '('), or logs it through tv_log when err is NULL, and returns
 * false. */
bool rnd_vk_ok(VkResult result, const char* call_text, char* err, size_t err_size);

#define RND_VK_OK(call, err, err_size) rnd_vk_ok((call), #call, (err), (err_size))

#endif
