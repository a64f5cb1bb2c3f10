/* trimvr shared configuration: included by C and by GLSL.
 * Only #define lines and comments: GLSL's preprocessor must accept every line,
 * so sizes and limits cannot drift between the host and the shaders. */
#ifndef TRIMVR_SHADER_CONFIG_H
#define TRIMVR_SHADER_CONFIG_H

/* Descriptor sets of the mesh pipeline (render/): the scene's buffers and
 * textures (shared, read-only), and the per-target subset id list. */
#define TV_SET_SCENE 0
#define TV_SET_DRAW  1

/* Bindings of set TV_SET_SCENE, except TV_BIND_DRAW_IDS (set TV_SET_DRAW). */
#define TV_BIND_POSITIONS 0   /* float[3] per welded vertex           */
#define TV_BIND_ATTRIBS   1   /* normal.xyz, uv.xy per vertex          */
#define TV_BIND_INDICES   2   /* uint[3] per triangle                  */
#define TV_BIND_TRI_MAT   3   /* material index per triangle           */
#define TV_BIND_MATERIALS 4   /* tv_material_gpu per material          */
#define TV_BIND_DRAW_IDS  5   /* triangle ids drawn (subset renders)   */
#define TV_BIND_TEXTURES  6   /* one sampler2DArray, a layer per texture */

/* Lighting of the mesh pass, linear RGB: one directional light (unit vector
 * towards the light) plus a hemispheric ambient blended by normal.y. */
#define TV_SUN_DIR     0.30151134, 0.90453403, 0.30151134
#define TV_SUN_COLOR   0.75, 0.75, 0.75
#define TV_SKY_COLOR   0.30, 0.32, 0.35
#define TV_GROUND_COLOR 0.12, 0.11, 0.10

/* Textures are layers of one sRGB 2D array image (lavapipe has no dynamic
 * indexing of sampler arrays and only 32 samplers per stage): at most
 * TV_MAX_TEXTURES layers, every layer resampled to the largest texture's
 * size capped at TV_MAX_TEXTURE_SIZE. */
#define TV_MAX_TEXTURES 256
#define TV_MAX_TEXTURE_SIZE 1024

/* Triangle id written where no triangle covers the pixel. */
#define TV_NO_TRIANGLE 0xFFFFFFFFu

/* Workgroup size of 1D compute passes. */
#define TV_WG_SIZE 64

/* Material flags (tv_material_gpu.flags). */
#define TV_MAT_TEXTURED   1u
#define TV_MAT_ALPHA_MASK 2u
#define TV_MAT_DOUBLE_SIDED 4u

/* Trim-region PVS, per-pixel k-buffers of P2 and the trim-sequence resolve of
 * P3 (pvs/resolve.h is the C reference the shaders mirror). Capacity per
 * pixel and kind; a counter above its K marks the pixel overflowed. */
#define TV_K_FRONT 32
#define TV_K_BACK  32
#define TV_K_TRIM  32
#define TV_K_UMBRA 32
#define TV_K_CARRY 16 /* entries one pixel carries from a layer to the next */
/* Most workgroups of P3's cooperative pass (Vulkan's minimum of
 * maxComputeWorkGroupCount[0]); each loops over the deferred pixels. */
#define TV_PVS_MAX_COOP_GROUPS 65535u
/* The wide visibility pass dilates triangles by half a pixel (pvs_face.vert).
 * A sharp corner needs an offset of about 0.7 / sin(angle / 2) pixels to keep
 * the whole triangle covered; this bound only guards the arithmetic (it keeps
 * corners down to 0.02 degrees). */
#define TV_PVS_MAX_DILATION_PX 4096.0
/* pvs_face.frag's depth tie: two faces within this many times the depth
 * slope per pixel (|dw/dx| + |dw/dy|) of each other count as tied (it was the
 * old 3-pixel dilation limit, the dilated plane's depth error). */
#define TV_PVS_TIE_SLOPES 3.0
/* The trim quads drawn in a face's plane move this fraction of their depth
 * towards the solid (pvs_quad.vert): far above the rounding of interpolated
 * depths (about 1e-7), far below the thickness of thin walls (1 cm at 100 m
 * is 1e-4). */
#define TV_PVS_TRIM_NUDGE 1e-5
/* A culled back (TV_ID_CULLED) enters P2's lists this fraction of its depth
 * farther: a single-sided surface exported as two coincident faces of
 * opposite winding (BSP levels) rounds either way, and where the culled twin
 * sorted first it was a lone back the walk skips, leaving the front without
 * a back: a run carried through every later layer until its carry
 * overflowed (oa:czest2ctf: PVS 2 -> 28 % of the scene). Twice
 * TV_PVS_TRIM_NUDGE, so a trim in the twin's plane still lies inside. */
#define TV_PVS_CULLED_NUDGE 2e-5

/* The trim drawn at the farther plane depth is drawn only for silhouettes
 * whose front triangle v* sees within this cosine of edge-on (beyond 60
 * degrees from its normal): 0.5 kept every FN gain of drawing it always on
 * Sponza and the city, 0.3 lost 0.1 px and 0.1 lost 6 px on Sponza at 20 cm
 * (docs/journal/2026-11-23-24-trim-draws-and-cracks.md). */
#define TV_PVS_GRAZING_COS 0.5
/* Widest gap (scene units, metres) between two border edges that counts as
 * a crack (scn_mark_cracks): Sponza's decimated columns gape up to ~1.2 cm
 * at their corners. */
#define TV_PVS_CRACK_GAP_M 0.02f
/* A crack edge's trim lies in its own triangle's plane; the face seen
 * beside the crack may be a neighbour a few mm behind that plane (measured
 * 6 mm on a Sponza column base). An interval whose front lies up to this
 * depth (view-axis metres) behind such a trim is seen through the crack. */
#define TV_PVS_CRACK_SLACK_M 0.04f

/* Trim-region stencil values (one per pixel, initialised UNTRIMMED). */
#define TV_STENCIL_UNTRIMMED 0u
#define TV_STENCIL_TRIMMED   1u
#define TV_STENCIL_SEALED    2u
#define TV_STENCIL_OVERFLOW  3u /* lost entries: every later front is output, never sealed */

/* Trim-sequence entry kinds. The value is also the tie-break rank when two
 * entries have equal depth: an umbra end sorts first (what lies exactly on
 * it is not hidden) and a range begin last (what lies exactly on it is not
 * hidden either); fronts before trims before backs, so a trim at the depth
 * of either face lies inside the interval. */
#define TV_ENTRY_END   0u /* end of a hidden range: umbra of a validated interval */
#define TV_ENTRY_FRONT 1u
#define TV_ENTRY_TRIM  2u
#define TV_ENTRY_BACK  3u
#define TV_ENTRY_BEGIN 4u /* start of a hidden range carried from an earlier layer */
#define TV_ENTRY_UMBRA 5u /* an umbra fragment as rasterised (looked up by region) */

/* Flag on a front's triangle id: a candidate front, i.e. a triangle that
 * touches the pixel without covering its centre (P2's dilated pass). It is
 * output when not hidden but never occludes: it neither starts an interval
 * nor terminates the pixel. On a back's id (a candidate back: the back of a
 * triangle narrower than a pixel) the same, but output only in front of
 * every face at the centre. Triangle ids stay below it. */
#define TV_ID_CANDIDATE 0x80000000u

/* Id of the "prior" face entries: the nearest faces (from v*) covering a
 * pixel's centre up to the layer in which the pixel becomes trimmed. Until
 * then the visibility buffer alone resolved the pixel, so P3 had kept none of
 * its faces; they enter the trim sequence as faces with this id and are never
 * output (the visibility buffer already holds them). Triangle ids stay below
 * it. */
#define TV_ID_PRIOR 0x7FFFFFFFu
/* Flag on a back's triangle id: a straddled back, whose plane the viewcell
 * straddles (P1), so that some eyes see its front while v* sees its back (a
 * side face seen edge-on past an occluder's edge). Where it closes an
 * interval, it is output with that interval's first front when the walk
 * reaches it unhidden, as the back of a cracked interval is. Triangle ids
 * stay below it; the prior ids, which have it, are recognised by
 * TV_ID_CULLED. */
#define TV_ID_STRADDLED 0x20000000u

/* The prior culled back (TV_ID_CULLED): it closes a prior front's interval
 * and is otherwise skipped like every culled back. */
#define TV_ID_PRIOR_CULLED 0x7FFFFFFEu

/* Flag on a back's triangle id: a culled back, the back of a triangle whose
 * material is single-sided (glTF doubleSided false) and whose plane has the
 * whole viewcell behind it (P1, pvs_classify.comp). The renderer culls it
 * from every eye of the viewcell, so it is never visible and hides nothing:
 * it only closes the interval its front opened. It is never output, never
 * terminates a pixel and is not a prior face. Triangle ids stay below it
 * (it shares its bit with TV_REGION_CRACK, which flags region ids). */
#define TV_ID_CULLED 0x40000000u

/* Flag on a trim-region id: the region of a crack edge (scn_mark_cracks),
 * a border edge along which another triangle's border edge runs across a
 * narrow gap. An interval whose front lies at or up to
 * TV_PVS_CRACK_SLACK_M behind such a region's trim has a hole at its front
 * surface, through which the eyes of the viewcell see its back face: P3
 * outputs that back (pvs_resolve_pixel). Region ids stay below it;
 * TV_ID_PRIOR, which has this bit, is never a crack region. */
#define TV_REGION_CRACK 0x40000000u

/* Adjacency value the GPU copy gives a crack edge (P1): a border edge, like
 * SCN_EDGE_BORDER and SCN_EDGE_NONMANIFOLD above it. */
#define TV_ADJ_CRACK 0xFFFFFFFDu

#endif
