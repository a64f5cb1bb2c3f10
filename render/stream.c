/* stream.c - per-thread command recording: one pool, one primary command
 * buffer, one fence and a timestamp pair per stream. Recording is
 * synchronous (record, submit, wait), which is what offscreen comparison
 * renders and the PVS worker need; the queue itself is shared via rnd_submit. */
#include "render_vk.h"

#include <string.h>

bool rnd_stream_create(rnd_context* ctx, rnd_stream* s, char* err, size_t err_size)
{
    memset(s, 0, sizeof *s);
    VkCommandPoolCreateInfo pool = {.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                    .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
                                    .queueFamilyIndex = ctx->queue_family};
    if (!RND_VK_OK(vkCreateCommandPool(ctx->device, &pool, NULL, &s->pool), err, err_size))
        goto fail;
    VkCommandBufferAllocateInfo alloc = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                         .commandPool = s->pool,
                                         .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                         .commandBufferCount = 1};
    if (!RND_VK_OK(vkAllocateCommandBuffers(ctx->device, &alloc, &s->cmd), err, err_size))
        goto fail;
    VkFenceCreateInfo fence = {.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    if (!RND_VK_OK(vkCreateFence(ctx->device, &fence, NULL, &s->fence), err, err_size))
        goto fail;
    if (ctx->timestamps) {
        VkQueryPoolCreateInfo query = {.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
                                       .queryType = VK_QUERY_TYPE_TIMESTAMP,
                                       .queryCount = 2};
        if (!RND_VK_OK(vkCreateQueryPool(ctx->device, &query, NULL, &s->timestamps), err, err_size))
            goto fail;
    }
    return true;
fail:
    rnd_stream_destroy(ctx, s);
    return false;
}

void rnd_stream_destroy(rnd_context* ctx, rnd_stream* s)
{
    if (s->timestamps)
        vkDestroyQueryPool(ctx->device, s->timestamps, NULL);
    if (s->fence)
        vkDestroyFence(ctx->device, s->fence, NULL);
    if (s->pool)
        vkDestroyCommandPool(ctx->device, s->pool, NULL);
    memset(s, 0, sizeof *s);
}

bool rnd_stream_begin(rnd_context* ctx, rnd_stream* s, char* err, size_t err_size)
{
    if (!RND_VK_OK(vkResetCommandPool(ctx->device, s->pool, 0), err, err_size))
        return false;
    VkCommandBufferBeginInfo begin = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                      .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    if (!RND_VK_OK(vkBeginCommandBuffer(s->cmd, &begin), err, err_size))
        return false;
    if (s->timestamps)
        vkCmdResetQueryPool(s->cmd, s->timestamps, 0, 2);
    return true;
}

bool rnd_stream_submit_wait(rnd_context* ctx, rnd_stream* s, char* err, size_t err_size)
{
    if (!RND_VK_OK(vkEndCommandBuffer(s->cmd), err, err_size) || !rnd_submit(ctx, s->cmd, s->fence, err, err_size))
        return false;
    bool ok = RND_VK_OK(vkWaitForFences(ctx->device, 1, &s->fence, VK_TRUE, UINT64_MAX), err, err_size);
    return RND_VK_OK(vkResetFences(ctx->device, 1, &s->fence), err, err_size) && ok;
}

void rnd_stream_timestamp(rnd_context* ctx, rnd_stream* s, uint32_t index)
{
    if (s->timestamps)
        vkCmdWriteTimestamp2(s->cmd, index == 0 ? VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT
                                                : VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT,
                             s->timestamps, index);
}

double rnd_stream_gpu_ms(rnd_context* ctx, rnd_stream* s)
{
    if (!s->timestamps)
        return -1.0;
    uint64_t ticks[2];
    VkResult r = vkGetQueryPoolResults(ctx->device, s->timestamps, 0, 2, sizeof ticks, ticks, sizeof ticks[0],
                                       VK_QUERY_RESULT_64_BIT);
    if (r != VK_SUCCESS) /* VK_NOT_READY: no timestamps were written in the last recording */
        return -1.0;
    /* modular difference: the counter may wrap within its valid bits */
    return (double)((ticks[1] - ticks[0]) & ctx->timestamp_mask) * ctx->props.limits.timestampPeriod * 1e-6;
}
