#include "octree.h"

#include <assert.h>
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "tri_box.h"

/* A node while building: `child` is the first of 8 children, 0 for a leaf
 * (the root is node 0 and never anybody's child). */
typedef struct build_node {
    uint32_t cell[3];
    uint32_t level;
    uint32_t child;
    uint32_t count;
    uint32_t* tris;
} build_node;

typedef struct builder {
    const scn_scene* scene;
    pvs_octree* tree;
    float* tri_bounds; /* 6 per triangle: min xyz, max xyz */
    build_node* nodes;
    uint32_t node_count, node_cap;
    bool out_of_memory;
} builder;

static float cell_coord(const pvs_octree* tree, int axis, uint32_t units)
{
    return tree->root_min[axis] + tree->root_size * ((float)units / (float)(1u << tree->max_depth));
}

static uint32_t node_side(const pvs_octree* tree, uint32_t level)
{
    return 1u << (tree->max_depth - level);
}

static void node_box(const pvs_octree* tree, const uint32_t cell[3], uint32_t level, float mn[3],
                     float mx[3])
{
    uint32_t side = node_side(tree, level);
    for (int a = 0; a < 3; a++) {
        mn[a] = cell_coord(tree, a, cell[a]);
        mx[a] = cell_coord(tree, a, cell[a] + side);
    }
}

static const float* vertex(const scn_scene* s, uint32_t tri, int corner)
{
    return s->positions + 3u * s->indices[3u * tri + (uint32_t)corner];
}

/* Appends 8 children of node `n` and moves its triangles into them. */
static bool split(builder* b, uint32_t n)
{
    if (b->node_count + 8 > b->node_cap) {
        uint32_t cap = b->node_cap * 2 + 64;
        build_node* grown = realloc(b->nodes, cap * sizeof *grown);
        if (!grown)
            return false;
        b->nodes = grown;
        b->node_cap = cap;
    }
    build_node parent = b->nodes[n];
    uint32_t first = b->node_count, half = node_side(b->tree, parent.level + 1);
    float cmin[8][3], cmax[8][3];
    memset(&b->nodes[first], 0, 8 * sizeof *b->nodes);
    b->node_count += 8; /* before allocating, so that a failure frees what exists */
    for (uint32_t c = 0; c < 8; c++) {
        build_node* ch = &b->nodes[first + c];
        for (int a = 0; a < 3; a++)
            ch->cell[a] = parent.cell[a] + (((c >> a) & 1u) ? half : 0u);
        ch->level = parent.level + 1;
        if (parent.count) {
            ch->tris = malloc(parent.count * sizeof *ch->tris);
            if (!ch->tris)
                return false;
        }
        node_box(b->tree, ch->cell, ch->level, cmin[c], cmax[c]);
    }
    for (uint32_t i = 0; i < parent.count; i++) {
        uint32_t t = parent.tris[i];
        const float* tb = b->tri_bounds + 6u * t;
        for (uint32_t c = 0; c < 8; c++) {
            bool apart = false, inside = true;
            for (int a = 0; a < 3; a++) {
                apart |= tb[a] > cmax[c][a] || tb[3 + a] < cmin[c][a];
                inside &= tb[a] >= cmin[c][a] && tb[3 + a] <= cmax[c][a];
            }
            if (apart)
                continue;
            if (inside || pvs_tri_box_overlap(vertex(b->scene, t, 0), vertex(b->scene, t, 1),
                                              vertex(b->scene, t, 2), cmin[c], cmax[c])) {
                build_node* ch = &b->nodes[first + c];
                ch->tris[ch->count++] = t;
            }
        }
    }
    for (uint32_t c = 0; c < 8; c++) {
        build_node* ch = &b->nodes[first + c];
        uint32_t* shrunk = ch->count ? realloc(ch->tris, ch->count * sizeof *ch->tris) : NULL;
        if (shrunk || !ch->count) {
            if (!ch->count)
                free(ch->tris);
            ch->tris = shrunk;
        }
    }
    free(parent.tris);
    b->nodes[n].tris = NULL;
    b->nodes[n].count = 0;
    b->nodes[n].child = first;
    return true;
}

/* Descends from the root towards finest-cell point p, stopping at a leaf or
 * at a node of `stop_level`. */
static uint32_t descend(const builder* b, const uint32_t p[3], uint32_t stop_level)
{
    uint32_t n = 0;
    while (b->nodes[n].child && b->nodes[n].level < stop_level) {
        const build_node* node = &b->nodes[n];
        uint32_t half = node_side(b->tree, node->level + 1), c = 0;
        for (int a = 0; a < 3; a++)
            c |= (p[a] >= node->cell[a] + half ? 1u : 0u) << a;
        n = node->child + c;
    }
    return n;
}

/* Calls visit() for the cells of level `level` (>= the node's level) that
 * touch face f of node n from outside and lie inside the root. */
typedef bool (*face_visit)(builder* b, uint32_t n, int face, uint32_t found, void* user);

static bool for_face_cells(builder* b, uint32_t n, int face, uint32_t level, face_visit visit,
                           void* user)
{
    const build_node node = b->nodes[n];
    uint32_t root = 1u << b->tree->max_depth, side = node_side(b->tree, node.level);
    uint32_t step = node_side(b->tree, level), m = side / step;
    int axis = face / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
    uint32_t p[3];
    if (face & 1) {
        if (node.cell[axis] + side >= root)
            return true;
        p[axis] = node.cell[axis] + side;
    } else {
        if (node.cell[axis] == 0)
            return true;
        p[axis] = node.cell[axis] - 1;
    }
    for (uint32_t i = 0; i < m; i++) {
        for (uint32_t j = 0; j < m; j++) {
            p[u] = node.cell[u] + i * step;
            p[v] = node.cell[v] + j * step;
            if (!visit(b, n, face, descend(b, p, level), user))
                return false;
        }
    }
    return true;
}

/* A face cell two levels finer that is still subdivided means a neighbour
 * more than two levels deeper: the visit stops and reports the violation. */
static bool visit_balance(builder* b, uint32_t n, int face, uint32_t found, void* user)
{
    return b->nodes[found].child == 0;
}

static bool build_tree(builder* b, const pvs_octree_desc* d)
{
    uint32_t cap = d->max_triangles_per_leaf, depth = b->tree->max_depth;
    for (uint32_t n = 0; n < b->node_count; n++) {
        if (b->nodes[n].count > cap && b->nodes[n].level < depth && !split(b, n))
            return false;
    }
    bool changed = true;
    while (changed) {
        changed = false;
        for (uint32_t n = 0; n < b->node_count; n++) {
            uint32_t level = b->nodes[n].level;
            if (b->nodes[n].child || level + 2 > depth)
                continue;
            for (int f = 0; f < 6; f++) {
                if (!for_face_cells(b, n, f, level + 2, visit_balance, NULL)) {
                    if (!split(b, n))
                        return false;
                    b->tree->balance_splits++;
                    changed = true;
                    break;
                }
            }
        }
    }
    return true;
}

typedef struct nbr_list {
    uint32_t* ids;
    uint32_t count, cap, face_begin;
    const uint32_t* leaf_of_node;
    bool failed;
} nbr_list;

static bool visit_neighbour(builder* b, uint32_t n, int face, uint32_t found, void* user)
{
    nbr_list* l = user;
    uint32_t leaf = l->leaf_of_node[found];
    for (uint32_t i = l->face_begin; i < l->count; i++) {
        if (l->ids[i] == leaf)
            return true;
    }
    if (l->count == l->cap) {
        uint32_t cap = l->cap * 2 + 1024;
        uint32_t* grown = realloc(l->ids, cap * sizeof *grown);
        if (!grown) {
            l->failed = true;
            return false;
        }
        l->ids = grown;
        l->cap = cap;
    }
    l->ids[l->count++] = leaf;
    return true;
}

static bool flatten(builder* b)
{
    pvs_octree* t = b->tree;
    uint32_t leaves = 0, refs = 0;
    for (uint32_t n = 0; n < b->node_count; n++) {
        if (!b->nodes[n].child) {
            leaves++;
            refs += b->nodes[n].count;
        }
    }
    t->leaf_count = leaves;
    t->node_count = b->node_count;
    t->leaves = calloc(leaves, sizeof *t->leaves);
    t->tri_offsets = calloc(leaves + 1, sizeof *t->tri_offsets);
    t->tri_ids = malloc((refs ? refs : 1) * sizeof *t->tri_ids);
    t->nbr_offsets = calloc(6u * leaves + 1, sizeof *t->nbr_offsets);
    t->nodes = calloc(b->node_count, sizeof *t->nodes);
    if (!t->leaves || !t->tri_offsets || !t->tri_ids || !t->nbr_offsets || !t->nodes)
        return false;
    uint32_t li = 0;
    for (uint32_t n = 0; n < b->node_count; n++) {
        const build_node* node = &b->nodes[n];
        if (node->child) {
            t->nodes[n] = node->child;
            continue;
        }
        pvs_leaf* leaf = &t->leaves[li];
        memcpy(leaf->cell, node->cell, sizeof leaf->cell);
        leaf->level = node->level;
        node_box(t, node->cell, node->level, leaf->min, leaf->max);
        if (node->count)
            memcpy(t->tri_ids + t->tri_offsets[li], node->tris, node->count * sizeof *node->tris);
        t->tri_offsets[li + 1] = t->tri_offsets[li] + node->count;
        t->nodes[n] = PVS_OCTREE_LEAF_BIT | li;
        li++;
    }
    uint32_t* leaf_of_node = malloc(b->node_count * sizeof *leaf_of_node);
    if (!leaf_of_node)
        return false;
    for (uint32_t n = 0; n < b->node_count; n++)
        leaf_of_node[n] = t->nodes[n] & ~PVS_OCTREE_LEAF_BIT;
    nbr_list l = {.leaf_of_node = leaf_of_node};
    li = 0;
    for (uint32_t n = 0; n < b->node_count && !l.failed; n++) {
        if (b->nodes[n].child)
            continue;
        uint32_t level = b->nodes[n].level + 2 < t->max_depth ? b->nodes[n].level + 2 : t->max_depth;
        for (int f = 0; f < 6 && !l.failed; f++) {
            l.face_begin = l.count;
            for_face_cells(b, n, f, level, visit_neighbour, &l);
            t->nbr_offsets[6u * li + (uint32_t)f + 1] = l.count;
        }
        li++;
    }
    free(leaf_of_node);
    t->nbr_ids = l.ids;
    return !l.failed;
}

static bool check_scene(const scn_scene* s, char* err, size_t err_size)
{
    assert(s->triangle_count == 0 || (s->indices && s->positions));
    for (uint32_t i = 0; i < 3u * s->triangle_count; i++) {
        if (s->indices[i] >= s->vertex_count) {
            snprintf(err, err_size, "scene '%s': triangle %u references vertex %u of %u", s->name,
                     i / 3, s->indices[i], s->vertex_count);
            return false;
        }
    }
    return true;
}

/* Root cube around the referenced vertices, padded so that no vertex lies on
 * the outer boundary after rounding. */
static bool compute_bounds(builder* b)
{
    const scn_scene* s = b->scene;
    pvs_octree* t = b->tree;
    float mn[3] = {FLT_MAX, FLT_MAX, FLT_MAX}, mx[3] = {-FLT_MAX, -FLT_MAX, -FLT_MAX};
    b->tri_bounds = malloc((s->triangle_count ? s->triangle_count : 1) * 6u * sizeof(float));
    if (!b->tri_bounds)
        return false;
    for (uint32_t tri = 0; tri < s->triangle_count; tri++) {
        float* tb = b->tri_bounds + 6u * tri;
        for (int a = 0; a < 3; a++) {
            tb[a] = FLT_MAX;
            tb[3 + a] = -FLT_MAX;
        }
        for (int c = 0; c < 3; c++) {
            const float* p = vertex(s, tri, c);
            for (int a = 0; a < 3; a++) {
                tb[a] = p[a] < tb[a] ? p[a] : tb[a];
                tb[3 + a] = p[a] > tb[3 + a] ? p[a] : tb[3 + a];
            }
        }
        for (int a = 0; a < 3; a++) {
            mn[a] = tb[a] < mn[a] ? tb[a] : mn[a];
            mx[a] = tb[3 + a] > mx[a] ? tb[3 + a] : mx[a];
        }
    }
    if (s->triangle_count == 0) {
        for (int a = 0; a < 3; a++)
            mn[a] = mx[a] = 0.0f;
    }
    float size = 0.0f;
    for (int a = 0; a < 3; a++)
        size = mx[a] - mn[a] > size ? mx[a] - mn[a] : size;
    size = size > 0.0f ? size * 1.001f : 1.0f;
    for (int a = 0; a < 3; a++)
        t->root_min[a] = 0.5f * (mn[a] + mx[a]) - 0.5f * size;
    t->root_size = size;
    return true;
}

bool pvs_octree_build(const pvs_octree_desc* desc, const scn_scene* scene, pvs_octree* out,
                      char* err, size_t err_size)
{
    assert(scene && out);
    double start = tv_now_ms();
    memset(out, 0, sizeof *out);
    pvs_octree_desc d = desc ? *desc : (pvs_octree_desc){0};
    d.max_triangles_per_leaf = d.max_triangles_per_leaf ? d.max_triangles_per_leaf : PVS_OCTREE_DEFAULT_CAP;
    d.max_depth = d.max_depth ? d.max_depth : PVS_OCTREE_DEFAULT_DEPTH;
    if (d.max_depth > PVS_OCTREE_MAX_DEPTH) {
        snprintf(err, err_size, "scene '%s': octree max_depth %u exceeds %u", scene->name,
                 d.max_depth, PVS_OCTREE_MAX_DEPTH);
        return false;
    }
    if (!check_scene(scene, err, err_size))
        return false;
    out->max_depth = d.max_depth;
    out->max_triangles_per_leaf = d.max_triangles_per_leaf;
    out->scene_triangle_count = scene->triangle_count;
    builder b = {.scene = scene, .tree = out};
    bool ok = compute_bounds(&b);
    if (ok) {
        b.node_cap = 64;
        b.nodes = calloc(b.node_cap, sizeof *b.nodes);
        b.node_count = 1;
        ok = b.nodes && (b.nodes[0].tris = malloc((scene->triangle_count + 1) * sizeof(uint32_t)));
    }
    if (ok) {
        for (uint32_t t = 0; t < scene->triangle_count; t++)
            b.nodes[0].tris[t] = t;
        b.nodes[0].count = scene->triangle_count;
        ok = build_tree(&b, &d) && flatten(&b);
    }
    for (uint32_t n = 0; n < b.node_count; n++)
        free(b.nodes[n].tris);
    free(b.nodes);
    free(b.tri_bounds);
    if (!ok) {
        pvs_octree_free(out);
        snprintf(err, err_size, "scene '%s': out of memory building the octree", scene->name);
        return false;
    }
    out->build_ms = tv_now_ms() - start;
    return true;
}

void pvs_octree_free(pvs_octree* tree)
{
    free(tree->leaves);
    free(tree->tri_offsets);
    free(tree->tri_ids);
    free(tree->nbr_offsets);
    free(tree->nbr_ids);
    free(tree->nodes);
    memset(tree, 0, sizeof *tree);
}

uint32_t pvs_octree_locate(const pvs_octree* tree, uint32_t x, uint32_t y, uint32_t z)
{
    uint32_t p[3] = {x, y, z}, n = 0, level = 0, cell[3] = {0, 0, 0};
    assert(x < (1u << tree->max_depth) && y < (1u << tree->max_depth) && z < (1u << tree->max_depth));
    while (!(tree->nodes[n] & PVS_OCTREE_LEAF_BIT)) {
        uint32_t half = node_side(tree, level + 1), c = 0;
        for (int a = 0; a < 3; a++) {
            if (p[a] >= cell[a] + half) {
                c |= 1u << a;
                cell[a] += half;
            }
        }
        n = tree->nodes[n] + c;
        level++;
    }
    return tree->nodes[n] & ~PVS_OCTREE_LEAF_BIT;
}
