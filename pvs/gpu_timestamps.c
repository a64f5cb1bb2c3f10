/* gpu_timestamps.c - the per-phase GPU timings of pvs_compute: a query pool
 * sized for the command buffer's timestamps, and their reading into
 * pvs_stats and the per-layer figures. */
#include "gpu_internal.h"

#include <stdlib.h>

/* Timestamps: one before everything, then per tile one after each of P1,
 * P2, P3 of every layer and one after P4. */
uint32_t pvs_timestamp_count(const pvs_context* ctx)
{
    return 1 + pvs_tile_count(&ctx->grid) * (3 * ctx->layers.layer_count + 1);
}

bool pvs_reserve_timestamps(pvs_context* ctx, uint32_t count, char* err, size_t err_size)
{
    if (!ctx->rnd->timestamps || count <= ctx->timestamp_capacity)
        return true;
    if (ctx->timestamps)
        vkDestroyQueryPool(ctx->rnd->device, ctx->timestamps, NULL);
    ctx->timestamps = VK_NULL_HANDLE;
    ctx->timestamp_capacity = 0;
    VkQueryPoolCreateInfo info = {.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
                                  .queryType = VK_QUERY_TYPE_TIMESTAMP,
                                  .queryCount = count + count / 2};
    if (!RND_VK_OK(vkCreateQueryPool(ctx->rnd->device, &info, NULL, &ctx->timestamps), err, err_size))
        return false;
    ctx->timestamp_capacity = info.queryCount;
    return true;
}

void pvs_timestamp(pvs_context* ctx, VkCommandBuffer cmd, uint32_t* index)
{
    if (ctx->timestamps)
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, ctx->timestamps, (*index)++);
}

/* Per-phase GPU milliseconds from the timestamps of record(), per layer and
 * in total, summed over tiles (each tile's first P1 includes its resets). */
void pvs_read_timestamps(pvs_context* ctx, pvs_stats* st)
{
    uint32_t n = pvs_timestamp_count(ctx);
    uint64_t* t = malloc(sizeof(uint64_t) * n);
    if (!t || vkGetQueryPoolResults(ctx->rnd->device, ctx->timestamps, 0, n, sizeof(uint64_t) * n, t,
                                    sizeof(uint64_t), VK_QUERY_RESULT_64_BIT) != VK_SUCCESS) {
        free(t);
        return;
    }
    const double period_ms = ctx->rnd->props.limits.timestampPeriod * 1e-6;
    uint32_t i = 1;
    for (uint32_t tile = 0; tile < pvs_tile_count(&ctx->grid); tile++, i++) {
        for (uint32_t l = 0; l < ctx->layers.layer_count; l++) {
            for (int p = 0; p < 3; p++, i++) {
                double ms = (double)(t[i] - t[i - 1]) * period_ms;
                st->ms[1 + p] += ms;
                ctx->per_layer[l].ms[p] += ms;
            }
        }
        st->ms[4] += (double)(t[i] - t[i - 1]) * period_ms;
    }
    free(t);
}
