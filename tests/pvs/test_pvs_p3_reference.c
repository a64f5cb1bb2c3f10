/* test_pvs_p3_reference.c - P3 on the GPU against its C reference,
 * pixel by pixel. White-box: it reaches into the context (gpu_internal.h)
 * to fill the k-buffers and pixel states of a 64x64 PVS with random
 * sequences (depths from a few values, so ties of every kind occur;
 * overflowing lists; carried runs, packed regions too, and hidden ranges; prior faces; sealed
 * pixels; see-through pixels, where most fronts are candidates as P2 enters
 * every see-through fragment, carried ones included), runs the P3 passes alone, and compares every pixel's output ids,
 * stencil, carry (a sealed pixel's terminator depth) and hidden range with
 * pvs_resolve_pixel. Each pixel outputs ids from its
 * own range, so a wrong id cannot hide behind another pixel's. Run once with
 * every sequence sorted per thread and once with every sequence of two or
 * more entries sorted by a workgroup (the hybrid sort's two passes). The
 * lists are written into the GPU's page pool by pvs_kbuf_push (the C
 * reference of P2's layout), which is starved at some pixels (chains cut
 * short, counters marked lost), and a few stored slots are punched into
 * holes; both sides read them back through the pages. Run in both k-buffer
 * layouts: for the flat one the C pool's chains are laid out in advance
 * where the GPU's flat addressing finds them (kb_flat_page: the front and back
 * lists in the pool, the trim and umbra lists in TV_PVS_BIND_KREGIONS, after it in the C pool), so the C
 * reference's paged addressing stands for both. Then once with every list
 * (nearly) full, per thread as lavapipe runs P3: llvmpipe's loop budget
 * (pvs_common.glsl) must last, which it did not while validate was cubic
 * (2,773 of 4,096 pixels apart at TV_K_* = 32). No run may spend it
 * (TV_PVS_C_LOOP_BUDGET). */
#include "gpu_internal.h"
#include "render_fixture.h"
#include "resolve.h"
#include "test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SIDE 64u
#define PIXELS (SIDE * SIDE)
#define IDS_PER_PIXEL 8u /* triangle ids of pixel p: [p * 8, p * 8 + 8) */
#define K TV_K_FRONT     /* the reference's capacity, so both truncate alike */
#define K_EXACT (K / 2) /* pvs_desc.k: a pixel with a longer list is deep (no umbrae) */
#define K_LISTS (3 * K / 4) /* pvs_desc.k_deep: the front and back lists hold fewer than the region list */

static rnd_context* g_rnd;
static uint32_t g_seed = 12345u;
static bool g_full; /* every list K - 1 or K entries long */

static uint32_t rnd_u(uint32_t n)
{
    g_seed = g_seed * 1664525u + 1013904223u;
    return (g_seed >> 8) % n;
}

/* One of six trim regions; regions 4 and 5 are crack regions, so their
 * trims and umbrae carry the flag alike. */
static uint32_t rnd_region(void)
{
    uint32_t r = rnd_u(6);
    return r >= 4 ? r | TV_REGION_CRACK : r;
}

static uint32_t fbits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

/* The six regions' front-patch labels (TV_PVS_BIND_PATCH after the triangles'), drawn per case. */
static uint32_t g_region_patch[6];

static float rnd_depth(void)
{
    return 0.1f * (float)(1 + rnd_u(10)); /* few values: ties */
}

/* List length: mostly short, sometimes long, sometimes overflowing. */
static uint32_t rnd_count(void)
{
    uint32_t r = rnd_u(20);
    if (g_full)
        return K - rnd_u(2);
    return r < 14 ? rnd_u(5) : r < 19 ? rnd_u(K + 1) : K + 1 + rnd_u(4);
}

typedef struct case_data {
    pvs_kbuf kbuf[PIXELS];
    pvs_pixel_state state[PIXELS];
} case_data;

/* P2's pushes of the random lists of `raw` (and `umbrae` of its umbrae)
 * into `pages`, from `heads` (NULL: empty lists; the entries past K
 * are lost as P2 loses them; the lost depths follow), with a pool that has
 * no page, or one, left at one pixel in eight; then one stored slot in
 * sixteen becomes a hole. kb gets the counters, heads and lost depths;
 * pvs_kbuf_read fills its arrays as P3 reads them. */
static void store_pixel(const pvs_kbuf* raw, uint32_t umbrae, pvs_kpages* pages, const uint32_t heads[TV_PVS_LISTS],
                        pvs_kbuf* kb)
{
    *kb = (pvs_kbuf){.k_exact = K_EXACT, .k_lists = K_LISTS, .nearest_front = raw->nearest_front,
                     .nearest_back = raw->nearest_back, .nearest_culled_back = raw->nearest_culled_back,
                     .culled_behind = raw->culled_behind, .region_patch = raw->region_patch,
                     .patch_centre = {raw->patch_centre[0], raw->patch_centre[1], raw->patch_centre[2],
                                      raw->patch_centre[3]},
                     .region_patches = raw->region_patches,
                     .front_lost = raw->front_lost, .candidate_lost = raw->candidate_lost, .trim_lost = raw->trim_lost};
    if (heads)
        memcpy(kb->head, heads, sizeof kb->head);
    uint32_t room = pages->page_count;
    if (rnd_u(8) == 0)
        pages->page_count = pages->taken + rnd_u(2);
    for (uint32_t i = 0; i < raw->front_count; i++)
        pvs_kbuf_push(kb, pages, TV_ENTRY_FRONT, raw->front_depth[i % K], raw->front_tri[i % K]);
    for (uint32_t i = 0; i < raw->back_count; i++)
        pvs_kbuf_push(kb, pages, TV_ENTRY_BACK, raw->back_depth[i % K], raw->back_tri[i % K]);
    for (uint32_t i = 0; i < raw->trim_count; i++)
        pvs_kbuf_push(kb, pages, TV_ENTRY_TRIM, raw->trim_depth[i % K], raw->trim_region[i % K]);
    for (uint32_t i = 0; i < umbrae; i++)
        pvs_kbuf_push(kb, pages, TV_ENTRY_UMBRA, raw->umbra_depth[i % K], raw->umbra_region[i % K]);
    pages->taken = pages->taken < pages->page_count ? pages->taken : pages->page_count;
    pages->page_count = room;
    /* the region list spans the trim and umbra lists' pages, and its counter is the trim list's */
    uint32_t* counts[TV_PVS_LISTS] = {&kb->front_count, &kb->back_count, &kb->trim_count, &kb->trim_count};
    for (uint32_t l = 0; l < TV_PVS_LISTS; l++) {
        if (kb->head[l] == TV_PVS_NO_PAGE || rnd_u(16) != 0)
            continue;
        pages->slots[TV_PVS_PAGE * (kb->head[l] - 1) + rnd_u(TV_PVS_PAGE)][0] = TV_PVS_HOLE;
        *counts[l] |= TV_PVS_COUNT_LOST; /* as P2 marks a list that lost an entry */
    }
    pvs_kbuf_read(kb, pages);
}

/* Returns how many umbrae to push (pvs_kbuf_push joins them to their regions). */
static uint32_t make_pixel(uint32_t p, pvs_kbuf* kb, pvs_pixel_state* st)
{
    memset(kb, 0, sizeof *kb);
    memset(st, 0, sizeof *st);
    uint32_t base = p * IDS_PER_PIXEL, r = rnd_u(10);
    st->stencil = r < 4 ? TV_STENCIL_UNTRIMMED : r < 8 ? TV_STENCIL_TRIMMED : r < 9 ? TV_STENCIL_SEALED
                                                                                   : TV_STENCIL_OVERFLOW;
    kb->front_count = rnd_count();
    kb->back_count = rnd_count();
    kb->trim_count = st->stencil == TV_STENCIL_UNTRIMMED && rnd_u(4) == 0 ? 0 : rnd_count();
    uint32_t umbrae = rnd_count();
    /* a quarter of the pixels see proxy boxes or panes (docs/trim-regions.md,
     * "See-through triangles and proxies"): three fronts in four candidates */
    bool see_through = rnd_u(4) == 0;
    for (uint32_t i = 0; i < K; i++) {
        kb->front_depth[i] = rnd_depth();
        bool candidate = see_through ? rnd_u(4) != 0 : rnd_u(4) == 0;
        kb->front_tri[i] = (base + rnd_u(IDS_PER_PIXEL)) | (candidate ? TV_ID_CANDIDATE : 0u);
        kb->back_depth[i] = rnd_depth();
        /* a quarter candidates, a quarter culled (P2 never makes both), a
         * quarter straddled (a candidate or not) */
        uint32_t back_kind = rnd_u(8);
        kb->back_tri[i] = (base + rnd_u(IDS_PER_PIXEL)) |
                          (back_kind < 2 ? TV_ID_CANDIDATE : back_kind < 4 ? TV_ID_CULLED : 0u) |
                          (back_kind == 1 || back_kind >= 6 ? TV_ID_STRADDLED : 0u);
        kb->trim_depth[i] = rnd_depth();
        kb->trim_region[i] = rnd_region();
        kb->umbra_depth[i] = rnd_depth() + 0.05f * (float)rnd_u(3);
        kb->umbra_region[i] = rnd_region();
    }
    kb->nearest_front = rnd_u(2) ? rnd_depth() : INFINITY;
    kb->nearest_back = rnd_u(2) ? rnd_depth() : INFINITY;
    kb->nearest_culled_back = rnd_u(2) ? rnd_depth() : INFINITY;
    kb->culled_behind = rnd_u(2) ? rnd_depth() : INFINITY;
    /* P2's front-patch slots (TV_PVS_CENTRE_PATCH_*): mostly one label at the prior front's depth, sometimes a tie
     * of two labels, a slot at another depth (the C side compares bits as P3 does) or none */
    uint32_t lab = rnd_u(4) == 0 ? TV_PVS_PATCH_NONE : rnd_u(3), f = fbits(kb->nearest_front);
    kb->patch_centre[0] = lab;
    kb->patch_centre[1] = rnd_u(6) == 0 ? fbits(rnd_depth()) : f;
    kb->patch_centre[2] = ~(rnd_u(6) == 0 ? rnd_u(3) : lab);
    kb->patch_centre[3] = rnd_u(6) == 0 ? fbits(rnd_depth()) : f;
    kb->region_patch = g_region_patch;
    kb->region_patches = 6;
    kb->front_lost = rnd_u(8) == 0 ? rnd_depth() : 0.0f;
    kb->candidate_lost = rnd_u(3) == 0 ? rnd_depth() : 0.0f; /* P3 then outputs stored candidates */
    kb->trim_lost = rnd_u(2) ? rnd_depth() : 0.0f; /* read when the trim list overflowed */
    if (st->stencil == TV_STENCIL_SEALED) {
        /* P2 stores nothing at a sealed pixel (it outputs the faces
         * pvs_sealed_output admits itself); P3 must keep its state */
        kb->front_count = kb->back_count = kb->trim_count = umbrae = 0;
        st->term_depth = rnd_depth();
        st->hide_begin = rnd_u(2) ? rnd_depth() : 0.0f;
        st->hide_end = st->hide_begin > 0.0f ? st->hide_begin + 0.1f : 0.0f;
    }
    if (st->stencil != TV_STENCIL_TRIMMED)
        return umbrae;
    /* a carried run: a front, then fronts, trims and their umbrae, in depth order; a trim's entry may
     * hold a second trim or its umbra (TV_CARRY_*, pvs_carry_add) */
    uint32_t n = rnd_u(6);
    float d = rnd_depth();
    for (uint32_t i = 0; i < n; i++) {
        uint32_t kind = i == 0 ? TV_ENTRY_FRONT : rnd_u(3) == 0 ? TV_ENTRY_UMBRA : rnd_u(2) ? TV_ENTRY_TRIM
                                                                                          : TV_ENTRY_FRONT;
        uint32_t id = kind == TV_ENTRY_FRONT ? base + rnd_u(IDS_PER_PIXEL) : rnd_region();
        if (kind == TV_ENTRY_FRONT && i > 0 && (see_through ? rnd_u(2) : rnd_u(4) == 0))
            id |= TV_ID_CANDIDATE; /* candidates behind the run's first front are carried */
        uint32_t packed = kind == TV_ENTRY_TRIM ? rnd_u(6) : 0;
        const uint32_t flags[6] = {0, 0, TV_CARRY_TWICE, TV_CARRY_TRIM2, TV_CARRY_UMBRA, TV_CARRY_TWICE | TV_CARRY_UMBRA};
        float second = flags[packed] & (TV_CARRY_TRIM2 | TV_CARRY_UMBRA) ? d + 0.1f * (float)rnd_u(3) : 0.0f;
        st->carry[st->carry_count++] = (pvs_entry){d, kind | flags[packed], id, second};
        d += 0.1f * (float)rnd_u(2);
    }
    if (rnd_u(3) == 0) { /* its footprints' end as carry_range leaves it: rounded, anywhere in the range */
        st->hide_begin = rnd_depth();
        float end = st->hide_begin + 0.1f * (float)(1 + rnd_u(3));
        end = pvs_umbra_pack(end, st->hide_begin + (end - st->hide_begin) * 0.25f * (float)rnd_u(5));
        st->hide_end = pvs_umbra_centre(end);
        st->hide_end_fp = pvs_umbra_footprint(end);
    }
    return umbrae;
}

/* The last word of a pixel's state (TV_PVS_BIND_PIXSTATE): while trimmed, hide_end packed with hide_end_fp. */
static uint32_t state_w(const pvs_pixel_state* st)
{
    return fbits(st->stencil == TV_STENCIL_TRIMMED ? pvs_umbra_pack(st->hide_end, st->hide_end_fp) : st->hide_end);
}

/* Host-visible copies of the buffers this test writes or reads. */
static bool make_host_visible(pvs_context* ctx)
{
    const uint32_t bindings[] = {TV_PVS_BIND_KPOOL, TV_PVS_BIND_KREGIONS, TV_PVS_BIND_KHEADS, TV_PVS_BIND_KLINKS, TV_PVS_BIND_PIXCOUNT, TV_PVS_BIND_PIXSTATE,
                                 TV_PVS_BIND_CARRY, TV_PVS_BIND_ACTIVE_LIST, TV_PVS_BIND_CENTRE_DEPTH,
                                 TV_PVS_BIND_LOST, TV_PVS_BIND_ACTIVE};
    char err[256];
    for (size_t i = 0; i < sizeof bindings / sizeof bindings[0]; i++) {
        rnd_buffer* b = &ctx->buffers[bindings[i]];
        VkDeviceSize size = b->size;
        rnd_buffer_destroy(ctx->rnd, b);
        if (!rnd_buffer_create(ctx->rnd, size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                               true, b, err, sizeof err)) {
            fprintf(stderr, "%s\n", err);
            return false;
        }
    }
    pvs_write_descriptors(ctx);
    return true;
}

static void upload(pvs_context* ctx, const case_data* c)
{
    uint32_t k = ctx->k;
    uint32_t* heads = ctx->buffers[TV_PVS_BIND_KHEADS].mapped;
    uint32_t* cnt = ctx->buffers[TV_PVS_BIND_PIXCOUNT].mapped;
    uint32_t* ps = ctx->buffers[TV_PVS_BIND_PIXSTATE].mapped;
    uint32_t* carry = ctx->buffers[TV_PVS_BIND_CARRY].mapped;
    uint32_t* active = ctx->buffers[TV_PVS_BIND_ACTIVE_LIST].mapped;
    uint32_t* centre = ctx->buffers[TV_PVS_BIND_CENTRE_DEPTH].mapped;
    uint32_t* lost = ctx->buffers[TV_PVS_BIND_LOST].mapped;
    for (uint32_t p = 0; p < PIXELS; p++) {
        const pvs_kbuf* kb = &c->kbuf[p];
        const pvs_pixel_state* st = &c->state[p];
        if (ctx->kb_paged) /* flat: no heads */
            memcpy(heads + TV_PVS_LISTS * p, kb->head, sizeof kb->head);
        uint32_t counts[4] = {kb->front_count, kb->back_count, kb->trim_count, 0};
        memcpy(cnt + 4 * p, counts, sizeof counts);
        uint32_t state[4] = {st->stencil, st->stencil == TV_STENCIL_SEALED ? fbits(st->term_depth) : st->carry_count,
                             fbits(st->hide_begin), state_w(st)};
        memcpy(ps + 4 * p, state, sizeof state);
        for (uint32_t i = 0; i < st->carry_count; i++) {
            uint32_t e[4] = {fbits(st->carry[i].depth), st->carry[i].kind, st->carry[i].id, fbits(st->carry[i].second)};
            memcpy(carry + 4 * (p * TV_K_CARRY + i), e, sizeof e);
        }
        active[p] = p;
        centre[TV_PVS_CENTRE_STRIDE * p + TV_PVS_CENTRE_FRONT] = fbits(kb->nearest_front);
        centre[TV_PVS_CENTRE_STRIDE * p + TV_PVS_CENTRE_BACK] = fbits(kb->nearest_back);
        centre[TV_PVS_CENTRE_STRIDE * p + TV_PVS_CENTRE_CULLED] = fbits(kb->nearest_culled_back);
        centre[TV_PVS_CENTRE_STRIDE * p + TV_PVS_CENTRE_CULLED_BEHIND] = fbits(kb->culled_behind);
        memcpy(centre + TV_PVS_CENTRE_STRIDE * p + TV_PVS_CENTRE_PATCH_LO, kb->patch_centre, sizeof kb->patch_centre);
        uint32_t* l = lost + TV_PVS_LOST_STRIDE * p;
        l[TV_PVS_LOST_FRONT] = kb->front_lost > 0.0f ? fbits(kb->front_lost) : fbits(INFINITY);
        l[TV_PVS_LOST_CANDIDATE] = kb->candidate_lost > 0.0f ? fbits(kb->candidate_lost) : fbits(INFINITY);
        l[TV_PVS_LOST_TRIM] = fbits(kb->trim_lost);
    }
    uint32_t* patch = ctx->buffers[TV_PVS_BIND_PATCH].mapped;
    uint32_t drawn = (uint32_t)(ctx->buffers[TV_PVS_BIND_PATCH].size / 16);
    memset(patch, 0xFF, ctx->buffers[TV_PVS_BIND_PATCH].size);
    memcpy(patch + drawn, g_region_patch, sizeof g_region_patch);
    memset(ctx->buffers[TV_PVS_BIND_TRI_FLAGS].mapped, 0, ctx->buffers[TV_PVS_BIND_TRI_FLAGS].size);
    memset(ctx->buffers[TV_PVS_BIND_LAYER_STATS].mapped, 0, ctx->buffers[TV_PVS_BIND_LAYER_STATS].size);
    uint32_t* counters = ctx->buffers[TV_PVS_BIND_COUNTERS].mapped;
    memset(counters, 0, TV_PVS_C_COUNT * sizeof(uint32_t));
    counters[TV_PVS_C_ACTIVE] = PIXELS;
    counters[TV_PVS_C_DISPATCH] = (PIXELS + TV_WG_SIZE - 1) / TV_WG_SIZE;
    counters[TV_PVS_C_DISPATCH + 1] = counters[TV_PVS_C_DISPATCH + 2] = 1;
    counters[TV_PVS_C_DISPATCH_COOP + 1] = counters[TV_PVS_C_DISPATCH_COOP + 2] = 1;
    pvs_view_gpu* view = ctx->buffers[TV_PVS_BIND_VIEW].mapped;
    memset(view, 0, sizeof *view);
    view->width = view->height = SIDE;
    view->tile_w = view->tile_h = SIDE; /* one tile */
    view->k = k;
    view->k_exact = K_EXACT;
    view->k_lists = K_LISTS;
    view->k_regions = K;
    view->triangle_count = ctx->triangle_count;
}

static bool run_p3(pvs_context* ctx)
{
    char err[256];
    if (!rnd_stream_begin(ctx->rnd, &ctx->stream, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return false;
    }
    VkCommandBuffer cmd = ctx->stream.cmd;
    VkDescriptorSet sets[2];
    sets[TV_SET_SCENE] = ctx->gpu->set;
    sets[TV_PVS_SET] = ctx->set;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, ctx->layout, 0, 2, sets, 0, NULL);
    pvs_push push = {0};
    vkCmdPushConstants(cmd, ctx->layout,
                       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT, 0,
                       sizeof push, &push);
    pvs_record_resolve(ctx, cmd);
    pvs_host_barrier(cmd);
    if (!rnd_stream_submit_wait(ctx->rnd, &ctx->stream, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return false;
    }
    return true;
}

/* Compares every pixel; returns the number that differ (the first few printed). */
static uint32_t compare(pvs_context* ctx, case_data* c)
{
    const uint32_t* flags = ctx->buffers[TV_PVS_BIND_TRI_FLAGS].mapped;
    const uint32_t* ps = ctx->buffers[TV_PVS_BIND_PIXSTATE].mapped;
    const uint32_t* carry = ctx->buffers[TV_PVS_BIND_CARRY].mapped;
    const uint32_t* lost = ctx->buffers[TV_PVS_BIND_LOST].mapped;
    uint32_t bad = 0;
    for (uint32_t p = 0; p < PIXELS; p++) {
        uint32_t out[PVS_RESOLVE_MAX_OUTPUT], want = 0, got = 0;
        bool overflowed;
        uint32_t n = pvs_resolve_pixel(&c->state[p], &c->kbuf[p], out, &overflowed);
        for (uint32_t i = 0; i < n; i++)
            want |= 1u << (out[i] - p * IDS_PER_PIXEL);
        for (uint32_t i = 0; i < IDS_PER_PIXEL; i++)
            got |= flags[p * IDS_PER_PIXEL + i] ? 1u << i : 0u;
        const pvs_pixel_state* st = &c->state[p];
        /* a sealed pixel keeps its terminator's depth where the carry count was */
        bool sealed = st->stencil == TV_STENCIL_SEALED;
        bool same = want == got && ps[4 * p] == st->stencil &&
                    ps[4 * p + 1] == (sealed ? fbits(st->term_depth) : st->carry_count);
        if (same && st->hide_begin < st->hide_end)
            same = ps[4 * p + 2] == fbits(st->hide_begin) && ps[4 * p + 3] == state_w(st);
        /* where P3 requested the dilated spill draw (its bound left in the candidate slot), the spill span */
        const uint32_t* l = lost + TV_PVS_LOST_STRIDE * p;
        if (same && c->kbuf[p].front_count > K && st->stencil != TV_STENCIL_UNTRIMMED && l[TV_PVS_LOST_CANDIDATE])
            same = l[TV_PVS_LOST_SPAN_LO] == fbits(st->spill_lo) && l[TV_PVS_LOST_SPAN_HI] == fbits(st->spill_hi);
        for (uint32_t i = 0; same && !sealed && i < st->carry_count; i++) {
            const uint32_t* e = carry + 4 * (p * TV_K_CARRY + i);
            same = e[0] == fbits(st->carry[i].depth) && e[1] == st->carry[i].kind && e[2] == st->carry[i].id &&
                   e[3] == fbits(st->carry[i].second);
        }
        if (!same && bad++ < 5)
            printf("  pixel %u: ids 0x%02x (reference 0x%02x), stencil %u (%u), carry %u (%u)\n", p, got, want,
                   ps[4 * p], st->stencil, ps[4 * p + 1], st->carry_count);
    }
    return bad;
}

/* The flat layout as a paged one: every list a chain of K / TV_PVS_PAGE
 * pages from kb_flat_page (pvs_common.glsl), its slots holes until written;
 * `links` gets the chains, the pool the holes. */
static void lay_out_flat(pvs_kpages* pages, uint32_t heads[PIXELS][TV_PVS_LISTS])
{
    const uint32_t per_list = (K + TV_PVS_PAGE - 1) / TV_PVS_PAGE;
    memset(pages->slots, 0xFF, sizeof pages->slots[0] * TV_PVS_PAGE * pages->page_count);
    for (uint32_t p = 0; p < PIXELS; p++)
        for (uint32_t l = 0; l < TV_PVS_LISTS; l++) {
            uint32_t first = (l * PIXELS + p) * per_list;
            heads[p][l] = first + 1;
            for (uint32_t j = 0; j < per_list; j++)
                pages->links[first + j] = j + 1 < per_list ? first + j + 2 : TV_PVS_NO_PAGE;
        }
}

static void check(uint32_t coop_sort_min, pvs_kbuffer_layout layout, const char* what)
{
    scn_scene scene = {0};
    char err[512];
    /* only its triangle count matters: the tri_flags buffer holds every pixel's ids */
    TV_CHECK(scn_load("builtin:city?tris=40000", &scene, err, sizeof err));
    TV_CHECK(scene.triangle_count >= PIXELS * IDS_PER_PIXEL);
    rnd_gpu_scene* gpu = rnd_scene_create(g_rnd, &scene, err, sizeof err);
    pvs_context* ctx = gpu ? pvs_create(g_rnd, &scene, gpu,
                                        &(pvs_desc){.width = SIDE, .height = SIDE, .k = K,
                                                    .coop_sort_min = coop_sort_min, .kbuffer_layout = layout,
                                                    .kbuffer_pages = PIXELS * TV_PVS_LISTS * K / TV_PVS_PAGE},
                                        err, sizeof err)
                           : NULL;
    case_data* c = malloc(sizeof *c);
    uint32_t(*heads)[TV_PVS_LISTS] = malloc(sizeof *heads * PIXELS);
    const uint32_t all_pages = PIXELS * TV_PVS_LISTS * K / TV_PVS_PAGE;
    uint32_t* flat_links = malloc(sizeof *flat_links * all_pages);
    uint32_t(*flat_slots)[2] = malloc(sizeof *flat_slots * TV_PVS_PAGE * all_pages);
    TV_CHECK(ctx && c && heads && flat_links && flat_slots && make_host_visible(ctx));
    if (ctx && c && heads && flat_links && flat_slots) {
        bool flat = layout == PVS_KBUFFER_FLAT;
        /* flat: the pool and TV_PVS_BIND_KREGIONS, half of the four lists each */
        TV_CHECK(ctx->kb_paged == !flat && ctx->pool_pages == (flat ? all_pages / 2 : all_pages));
        pvs_kpages pages = {flat ? flat_slots : ctx->buffers[TV_PVS_BIND_KPOOL].mapped,
                            flat ? flat_links : ctx->buffers[TV_PVS_BIND_KLINKS].mapped, all_pages, 0};
        if (flat)
            lay_out_flat(&pages, heads);
        uint32_t lost = 0;
        for (uint32_t r = 0; r < 6; r++) /* a region of no patch, of the prior front's or of another */
            g_region_patch[r] = rnd_u(4) == 0 ? TV_PVS_PATCH_NONE : rnd_u(3);
        for (uint32_t p = 0; p < PIXELS; p++) {
            pvs_kbuf raw;
            uint32_t umbrae = make_pixel(p, &raw, &c->state[p]);
            store_pixel(&raw, umbrae, &pages, flat ? heads[p] : NULL, &c->kbuf[p]);
            lost += (c->kbuf[p].front_count | c->kbuf[p].trim_count) >= TV_PVS_COUNT_LOST;
        }
        TV_CHECK(lost > PIXELS / 32 && pages.taken < all_pages && (!flat || pages.taken == 0));
        if (flat) {
            size_t half = sizeof *flat_slots * TV_PVS_PAGE * (all_pages / 2);
            memcpy(ctx->buffers[TV_PVS_BIND_KPOOL].mapped, flat_slots, half);
            memcpy(ctx->buffers[TV_PVS_BIND_KREGIONS].mapped, flat_slots + TV_PVS_PAGE * (all_pages / 2), half);
        }
        upload(ctx, c);
        TV_CHECK(run_p3(ctx));
        const uint32_t* counters = ctx->buffers[TV_PVS_BIND_COUNTERS].mapped;
        uint32_t coop = counters[TV_PVS_C_COOP_TOTAL], spent = counters[TV_PVS_C_LOOP_BUDGET];
        uint32_t bad = compare(ctx, c);
        printf("  %s, %s: %u of %u pixels differ from pvs_resolve_pixel (%u sorted by a workgroup, %u out of "
               "loop budget)\n", what, flat ? "flat" : "paged", bad, PIXELS, coop, spent);
        TV_CHECK(bad == 0 && spent == 0);
        TV_CHECK(coop_sort_min == UINT32_MAX ? coop == 0 : coop > PIXELS / 4);
    }
    free(flat_slots);
    free(flat_links);
    free(heads);
    free(c);
    pvs_destroy(ctx);
    rnd_scene_destroy(g_rnd, gpu);
    scn_scene_free(&scene);
}

static void test_per_thread(void)
{
    check(UINT32_MAX, PVS_KBUFFER_PAGED, "per thread");
    check(UINT32_MAX, PVS_KBUFFER_FLAT, "per thread");
}

static void test_workgroups(void)
{
    check(2, PVS_KBUFFER_PAGED, "workgroups");
    check(2, PVS_KBUFFER_FLAT, "workgroups");
}

static void test_full_lists(void)
{
    g_full = true;
    check(UINT32_MAX, PVS_KBUFFER_PAGED, "full lists, per thread");
    g_full = false;
}

int main(void)
{
    g_rnd = fx_context();
    TV_TEST_RUN(test_per_thread);
    TV_TEST_RUN(test_workgroups);
    TV_TEST_RUN(test_full_lists);
    TV_CHECK(rnd_validation_message_count(g_rnd) == 0);
    rnd_destroy(g_rnd);
    return tv_test_finish();
}
