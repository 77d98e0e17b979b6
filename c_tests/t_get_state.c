/* t_get_state: the state queries (GL 1.5 section 6.1, state tables 6.5 to
 * 6.36) on a fresh OSMesa RGBA context (24 depth, 8 stencil, no accum).
 *
 * - Every name of the tables that glGet* answers is accepted by all four of
 *   glGetBooleanv, glGetIntegerv, glGetFloatv and glGetDoublev, with the
 *   same number of values from each.
 * - Initial values are the tables' (for implementation limits: at least the
 *   table's minimum).
 * - The type conversions of 6.1.2: a boolean is true where the value is
 *   non-zero; integer state reads back as the rounded value; colours, the
 *   normal, the depth range and the depth clear value map [-1, 1] onto the
 *   integers, so 1.0 gives the largest GLint and 0.0 gives 0.
 * - A name outside the tables gives GL_INVALID_ENUM and writes nothing.
 * - glReadPixels into signed types uses the same mapping (table 2.9
 *   inverted, ((2^b - 1) c - 1) / 2): 0 reads back as 0, 1 as the largest.
 */
#include "harness.h"
#include <GL/glext.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>

#define W 64
#define H 64
#define SENTINEL 0x7eadbeef
#define MAXV 32

/* How a row's values are checked. */
enum kind {
    EXACT,   /* every value equals v[] */
    AT_LEAST,/* every value is at least v[0] */
    ANY,     /* only accepted, with n values */
    IDENTITY /* a 4x4 identity matrix */
};

struct row {
    GLenum e;
    const char *name;
    int n;
    enum kind kind;
    double v[4];
};

#define R(e, n, k, ...) {e, #e, n, k, {__VA_ARGS__}}

static const struct row rows[] = {
    /* 6.5 current values */
    R(GL_CURRENT_COLOR, 4, EXACT, 1, 1, 1, 1),
    R(GL_CURRENT_SECONDARY_COLOR, 4, EXACT, 0, 0, 0, 1),
    R(GL_CURRENT_INDEX, 1, EXACT, 1),
    R(GL_CURRENT_TEXTURE_COORDS, 4, EXACT, 0, 0, 0, 1),
    R(GL_CURRENT_NORMAL, 3, EXACT, 0, 0, 1),
    R(GL_CURRENT_FOG_COORD, 1, EXACT, 0),
    R(GL_CURRENT_RASTER_POSITION, 4, EXACT, 0, 0, 0, 1),
    R(GL_CURRENT_RASTER_DISTANCE, 1, EXACT, 0),
    R(GL_CURRENT_RASTER_COLOR, 4, EXACT, 1, 1, 1, 1),
    R(GL_CURRENT_RASTER_INDEX, 1, EXACT, 1),
    R(GL_CURRENT_RASTER_TEXTURE_COORDS, 4, EXACT, 0, 0, 0, 1),
    R(GL_CURRENT_RASTER_POSITION_VALID, 1, EXACT, 1),
    R(GL_EDGE_FLAG, 1, EXACT, 1),
    /* 6.6, 6.7 vertex arrays and their buffers */
    R(GL_CLIENT_ACTIVE_TEXTURE, 1, EXACT, GL_TEXTURE0),
    R(GL_VERTEX_ARRAY, 1, EXACT, 0),
    R(GL_VERTEX_ARRAY_SIZE, 1, EXACT, 4),
    R(GL_VERTEX_ARRAY_TYPE, 1, EXACT, GL_FLOAT),
    R(GL_VERTEX_ARRAY_STRIDE, 1, EXACT, 0),
    R(GL_NORMAL_ARRAY, 1, EXACT, 0),
    R(GL_NORMAL_ARRAY_TYPE, 1, EXACT, GL_FLOAT),
    R(GL_NORMAL_ARRAY_STRIDE, 1, EXACT, 0),
    R(GL_FOG_COORD_ARRAY, 1, EXACT, 0),
    R(GL_FOG_COORD_ARRAY_TYPE, 1, EXACT, GL_FLOAT),
    R(GL_FOG_COORD_ARRAY_STRIDE, 1, EXACT, 0),
    R(GL_COLOR_ARRAY, 1, EXACT, 0),
    R(GL_COLOR_ARRAY_SIZE, 1, EXACT, 4),
    R(GL_COLOR_ARRAY_TYPE, 1, EXACT, GL_FLOAT),
    R(GL_COLOR_ARRAY_STRIDE, 1, EXACT, 0),
    R(GL_SECONDARY_COLOR_ARRAY, 1, EXACT, 0),
    R(GL_SECONDARY_COLOR_ARRAY_SIZE, 1, EXACT, 3),
    R(GL_SECONDARY_COLOR_ARRAY_TYPE, 1, EXACT, GL_FLOAT),
    R(GL_SECONDARY_COLOR_ARRAY_STRIDE, 1, EXACT, 0),
    R(GL_INDEX_ARRAY, 1, EXACT, 0),
    R(GL_INDEX_ARRAY_TYPE, 1, EXACT, GL_FLOAT),
    R(GL_INDEX_ARRAY_STRIDE, 1, EXACT, 0),
    R(GL_TEXTURE_COORD_ARRAY, 1, EXACT, 0),
    R(GL_TEXTURE_COORD_ARRAY_SIZE, 1, EXACT, 4),
    R(GL_TEXTURE_COORD_ARRAY_TYPE, 1, EXACT, GL_FLOAT),
    R(GL_TEXTURE_COORD_ARRAY_STRIDE, 1, EXACT, 0),
    R(GL_EDGE_FLAG_ARRAY, 1, EXACT, 0),
    R(GL_EDGE_FLAG_ARRAY_STRIDE, 1, EXACT, 0),
    R(GL_ARRAY_BUFFER_BINDING, 1, EXACT, 0),
    R(GL_VERTEX_ARRAY_BUFFER_BINDING, 1, EXACT, 0),
    R(GL_NORMAL_ARRAY_BUFFER_BINDING, 1, EXACT, 0),
    R(GL_COLOR_ARRAY_BUFFER_BINDING, 1, EXACT, 0),
    R(GL_INDEX_ARRAY_BUFFER_BINDING, 1, EXACT, 0),
    R(GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, 1, EXACT, 0),
    R(GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, 1, EXACT, 0),
    R(GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING, 1, EXACT, 0),
    R(GL_FOG_COORD_ARRAY_BUFFER_BINDING, 1, EXACT, 0),
    R(GL_ELEMENT_ARRAY_BUFFER_BINDING, 1, EXACT, 0),
    /* 6.8, 6.9 transformation */
    R(GL_MODELVIEW_MATRIX, 16, IDENTITY, 0),
    R(GL_PROJECTION_MATRIX, 16, IDENTITY, 0),
    R(GL_TEXTURE_MATRIX, 16, IDENTITY, 0),
    R(GL_TRANSPOSE_MODELVIEW_MATRIX, 16, IDENTITY, 0),
    R(GL_TRANSPOSE_PROJECTION_MATRIX, 16, IDENTITY, 0),
    R(GL_TRANSPOSE_TEXTURE_MATRIX, 16, IDENTITY, 0),
    R(GL_VIEWPORT, 4, EXACT, 0, 0, W, H),
    R(GL_DEPTH_RANGE, 2, EXACT, 0, 1),
    R(GL_MODELVIEW_STACK_DEPTH, 1, EXACT, 1),
    R(GL_PROJECTION_STACK_DEPTH, 1, EXACT, 1),
    R(GL_TEXTURE_STACK_DEPTH, 1, EXACT, 1),
    R(GL_MATRIX_MODE, 1, EXACT, GL_MODELVIEW),
    R(GL_NORMALIZE, 1, EXACT, 0),
    R(GL_RESCALE_NORMAL, 1, EXACT, 0),
    R(GL_CLIP_PLANE0, 1, EXACT, 0),
    R(GL_CLIP_PLANE5, 1, EXACT, 0),
    /* 6.10 colouring */
    R(GL_FOG_COLOR, 4, EXACT, 0, 0, 0, 0),
    R(GL_FOG_INDEX, 1, EXACT, 0),
    R(GL_FOG_DENSITY, 1, EXACT, 1),
    R(GL_FOG_START, 1, EXACT, 0),
    R(GL_FOG_END, 1, EXACT, 1),
    R(GL_FOG_MODE, 1, EXACT, GL_EXP),
    R(GL_FOG, 1, EXACT, 0),
    R(GL_FOG_COORD_SRC, 1, EXACT, GL_FRAGMENT_DEPTH),
    R(GL_COLOR_SUM, 1, EXACT, 0),
    R(GL_SHADE_MODEL, 1, EXACT, GL_SMOOTH),
    /* 6.11 lighting */
    R(GL_LIGHTING, 1, EXACT, 0),
    R(GL_COLOR_MATERIAL, 1, EXACT, 0),
    R(GL_COLOR_MATERIAL_PARAMETER, 1, EXACT, GL_AMBIENT_AND_DIFFUSE),
    R(GL_COLOR_MATERIAL_FACE, 1, EXACT, GL_FRONT_AND_BACK),
    R(GL_LIGHT_MODEL_AMBIENT, 4, EXACT, 0.2, 0.2, 0.2, 1),
    R(GL_LIGHT_MODEL_LOCAL_VIEWER, 1, EXACT, 0),
    R(GL_LIGHT_MODEL_TWO_SIDE, 1, EXACT, 0),
    R(GL_LIGHT_MODEL_COLOR_CONTROL, 1, EXACT, GL_SINGLE_COLOR),
    R(GL_LIGHT0, 1, EXACT, 0),
    R(GL_LIGHT7, 1, EXACT, 0),
    /* 6.12 rasterization */
    R(GL_POINT_SIZE, 1, EXACT, 1),
    R(GL_POINT_SMOOTH, 1, EXACT, 0),
    R(GL_POINT_SIZE_MIN, 1, EXACT, 0),
    R(GL_POINT_SIZE_MAX, 1, AT_LEAST, 1),
    R(GL_POINT_FADE_THRESHOLD_SIZE, 1, EXACT, 1),
    R(GL_POINT_DISTANCE_ATTENUATION, 3, EXACT, 1, 0, 0),
    R(GL_LINE_WIDTH, 1, EXACT, 1),
    R(GL_LINE_SMOOTH, 1, EXACT, 0),
    R(GL_LINE_STIPPLE_PATTERN, 1, EXACT, 0xFFFF),
    R(GL_LINE_STIPPLE_REPEAT, 1, EXACT, 1),
    R(GL_LINE_STIPPLE, 1, EXACT, 0),
    R(GL_CULL_FACE, 1, EXACT, 0),
    R(GL_CULL_FACE_MODE, 1, EXACT, GL_BACK),
    R(GL_FRONT_FACE, 1, EXACT, GL_CCW),
    R(GL_POLYGON_SMOOTH, 1, EXACT, 0),
    R(GL_POLYGON_MODE, 2, EXACT, GL_FILL, GL_FILL),
    R(GL_POLYGON_OFFSET_FACTOR, 1, EXACT, 0),
    R(GL_POLYGON_OFFSET_UNITS, 1, EXACT, 0),
    R(GL_POLYGON_OFFSET_POINT, 1, EXACT, 0),
    R(GL_POLYGON_OFFSET_LINE, 1, EXACT, 0),
    R(GL_POLYGON_OFFSET_FILL, 1, EXACT, 0),
    R(GL_POLYGON_STIPPLE, 1, EXACT, 0),
    /* 6.13 multisampling */
    R(GL_MULTISAMPLE, 1, EXACT, 1),
    R(GL_SAMPLE_ALPHA_TO_COVERAGE, 1, EXACT, 0),
    R(GL_SAMPLE_ALPHA_TO_ONE, 1, EXACT, 0),
    R(GL_SAMPLE_COVERAGE, 1, EXACT, 0),
    R(GL_SAMPLE_COVERAGE_VALUE, 1, EXACT, 1),
    R(GL_SAMPLE_COVERAGE_INVERT, 1, EXACT, 0),
    /* 6.14 to 6.18 textures (the active unit's bindings and enables) */
    R(GL_ACTIVE_TEXTURE, 1, EXACT, GL_TEXTURE0),
    R(GL_TEXTURE_1D, 1, EXACT, 0),
    R(GL_TEXTURE_2D, 1, EXACT, 0),
    R(GL_TEXTURE_3D, 1, EXACT, 0),
    R(GL_TEXTURE_CUBE_MAP, 1, EXACT, 0),
    R(GL_TEXTURE_BINDING_1D, 1, EXACT, 0),
    R(GL_TEXTURE_BINDING_2D, 1, EXACT, 0),
    R(GL_TEXTURE_BINDING_3D, 1, EXACT, 0),
    R(GL_TEXTURE_BINDING_CUBE_MAP, 1, EXACT, 0),
    R(GL_TEXTURE_GEN_S, 1, EXACT, 0),
    R(GL_TEXTURE_GEN_T, 1, EXACT, 0),
    R(GL_TEXTURE_GEN_R, 1, EXACT, 0),
    R(GL_TEXTURE_GEN_Q, 1, EXACT, 0),
    /* 6.19, 6.20 pixel operations */
    R(GL_SCISSOR_TEST, 1, EXACT, 0),
    R(GL_SCISSOR_BOX, 4, EXACT, 0, 0, W, H),
    R(GL_ALPHA_TEST, 1, EXACT, 0),
    R(GL_ALPHA_TEST_FUNC, 1, EXACT, GL_ALWAYS),
    R(GL_ALPHA_TEST_REF, 1, EXACT, 0),
    R(GL_STENCIL_TEST, 1, EXACT, 0),
    R(GL_STENCIL_FUNC, 1, EXACT, GL_ALWAYS),
    R(GL_STENCIL_REF, 1, EXACT, 0),
    R(GL_STENCIL_VALUE_MASK, 1, EXACT, 255),
    R(GL_STENCIL_FAIL, 1, EXACT, GL_KEEP),
    R(GL_STENCIL_PASS_DEPTH_FAIL, 1, EXACT, GL_KEEP),
    R(GL_STENCIL_PASS_DEPTH_PASS, 1, EXACT, GL_KEEP),
    R(GL_DEPTH_TEST, 1, EXACT, 0),
    R(GL_DEPTH_FUNC, 1, EXACT, GL_LESS),
    R(GL_BLEND, 1, EXACT, 0),
    R(GL_BLEND_SRC_RGB, 1, EXACT, GL_ONE),
    R(GL_BLEND_SRC_ALPHA, 1, EXACT, GL_ONE),
    R(GL_BLEND_DST_RGB, 1, EXACT, GL_ZERO),
    R(GL_BLEND_DST_ALPHA, 1, EXACT, GL_ZERO),
    R(GL_BLEND_SRC, 1, EXACT, GL_ONE),
    R(GL_BLEND_DST, 1, EXACT, GL_ZERO),
    R(GL_BLEND_EQUATION, 1, EXACT, GL_FUNC_ADD),
    R(GL_BLEND_COLOR, 4, EXACT, 0, 0, 0, 0),
    R(GL_DITHER, 1, EXACT, 1),
    R(GL_INDEX_LOGIC_OP, 1, EXACT, 0),
    R(GL_COLOR_LOGIC_OP, 1, EXACT, 0),
    R(GL_LOGIC_OP_MODE, 1, EXACT, GL_COPY),
    /* 6.21 framebuffer control */
    R(GL_DRAW_BUFFER, 1, EXACT, GL_FRONT),
    R(GL_INDEX_WRITEMASK, 1, ANY, 0),
    R(GL_COLOR_WRITEMASK, 4, EXACT, 1, 1, 1, 1),
    R(GL_DEPTH_WRITEMASK, 1, EXACT, 1),
    /* 1's, within the 8 stencil bits (as Mesa reads them back) */
    R(GL_STENCIL_WRITEMASK, 1, EXACT, 255),
    R(GL_COLOR_CLEAR_VALUE, 4, EXACT, 0, 0, 0, 0),
    R(GL_INDEX_CLEAR_VALUE, 1, EXACT, 0),
    R(GL_DEPTH_CLEAR_VALUE, 1, EXACT, 1),
    R(GL_STENCIL_CLEAR_VALUE, 1, EXACT, 0),
    R(GL_ACCUM_CLEAR_VALUE, 4, EXACT, 0, 0, 0, 0),
    /* 6.22 to 6.26 pixels */
    R(GL_UNPACK_SWAP_BYTES, 1, EXACT, 0),
    R(GL_UNPACK_LSB_FIRST, 1, EXACT, 0),
    R(GL_UNPACK_IMAGE_HEIGHT, 1, EXACT, 0),
    R(GL_UNPACK_SKIP_IMAGES, 1, EXACT, 0),
    R(GL_UNPACK_ROW_LENGTH, 1, EXACT, 0),
    R(GL_UNPACK_SKIP_ROWS, 1, EXACT, 0),
    R(GL_UNPACK_SKIP_PIXELS, 1, EXACT, 0),
    R(GL_UNPACK_ALIGNMENT, 1, EXACT, 4),
    R(GL_PACK_SWAP_BYTES, 1, EXACT, 0),
    R(GL_PACK_LSB_FIRST, 1, EXACT, 0),
    R(GL_PACK_IMAGE_HEIGHT, 1, EXACT, 0),
    R(GL_PACK_SKIP_IMAGES, 1, EXACT, 0),
    R(GL_PACK_ROW_LENGTH, 1, EXACT, 0),
    R(GL_PACK_SKIP_ROWS, 1, EXACT, 0),
    R(GL_PACK_SKIP_PIXELS, 1, EXACT, 0),
    R(GL_PACK_ALIGNMENT, 1, EXACT, 4),
    R(GL_PIXEL_PACK_BUFFER_BINDING, 1, EXACT, 0),
    R(GL_PIXEL_UNPACK_BUFFER_BINDING, 1, EXACT, 0),
    R(GL_MAP_COLOR, 1, EXACT, 0),
    R(GL_MAP_STENCIL, 1, EXACT, 0),
    R(GL_INDEX_SHIFT, 1, EXACT, 0),
    R(GL_INDEX_OFFSET, 1, EXACT, 0),
    R(GL_RED_SCALE, 1, EXACT, 1),
    R(GL_GREEN_SCALE, 1, EXACT, 1),
    R(GL_BLUE_SCALE, 1, EXACT, 1),
    R(GL_ALPHA_SCALE, 1, EXACT, 1),
    R(GL_DEPTH_SCALE, 1, EXACT, 1),
    R(GL_RED_BIAS, 1, EXACT, 0),
    R(GL_GREEN_BIAS, 1, EXACT, 0),
    R(GL_BLUE_BIAS, 1, EXACT, 0),
    R(GL_ALPHA_BIAS, 1, EXACT, 0),
    R(GL_DEPTH_BIAS, 1, EXACT, 0),
    R(GL_ZOOM_X, 1, EXACT, 1),
    R(GL_ZOOM_Y, 1, EXACT, 1),
    R(GL_PIXEL_MAP_I_TO_I_SIZE, 1, EXACT, 1),
    R(GL_PIXEL_MAP_S_TO_S_SIZE, 1, EXACT, 1),
    R(GL_PIXEL_MAP_I_TO_R_SIZE, 1, EXACT, 1),
    R(GL_PIXEL_MAP_R_TO_R_SIZE, 1, EXACT, 1),
    R(GL_PIXEL_MAP_A_TO_A_SIZE, 1, EXACT, 1),
    R(GL_READ_BUFFER, 1, EXACT, GL_FRONT),
    /* 6.27 evaluators */
    R(GL_MAP1_VERTEX_3, 1, EXACT, 0),
    R(GL_MAP2_VERTEX_4, 1, EXACT, 0),
    R(GL_MAP1_GRID_DOMAIN, 2, EXACT, 0, 1),
    R(GL_MAP2_GRID_DOMAIN, 4, EXACT, 0, 1, 0, 1),
    R(GL_MAP1_GRID_SEGMENTS, 1, EXACT, 1),
    R(GL_MAP2_GRID_SEGMENTS, 2, EXACT, 1, 1),
    R(GL_AUTO_NORMAL, 1, EXACT, 0),
    /* 6.28 hints */
    R(GL_PERSPECTIVE_CORRECTION_HINT, 1, EXACT, GL_DONT_CARE),
    R(GL_POINT_SMOOTH_HINT, 1, EXACT, GL_DONT_CARE),
    R(GL_LINE_SMOOTH_HINT, 1, EXACT, GL_DONT_CARE),
    R(GL_POLYGON_SMOOTH_HINT, 1, EXACT, GL_DONT_CARE),
    R(GL_FOG_HINT, 1, EXACT, GL_DONT_CARE),
    R(GL_GENERATE_MIPMAP_HINT, 1, EXACT, GL_DONT_CARE),
    R(GL_TEXTURE_COMPRESSION_HINT, 1, EXACT, GL_DONT_CARE),
    /* 6.29 to 6.31 implementation limits (the tables' minimums) */
    R(GL_MAX_LIGHTS, 1, AT_LEAST, 8),
    R(GL_MAX_CLIP_PLANES, 1, AT_LEAST, 6),
    R(GL_MAX_MODELVIEW_STACK_DEPTH, 1, AT_LEAST, 32),
    R(GL_MAX_PROJECTION_STACK_DEPTH, 1, AT_LEAST, 2),
    R(GL_MAX_TEXTURE_STACK_DEPTH, 1, AT_LEAST, 2),
    R(GL_SUBPIXEL_BITS, 1, AT_LEAST, 4),
    R(GL_MAX_3D_TEXTURE_SIZE, 1, AT_LEAST, 16),
    R(GL_MAX_TEXTURE_SIZE, 1, AT_LEAST, 64),
    R(GL_MAX_CUBE_MAP_TEXTURE_SIZE, 1, AT_LEAST, 16),
    R(GL_MAX_TEXTURE_LOD_BIAS, 1, AT_LEAST, 4),
    R(GL_MAX_PIXEL_MAP_TABLE, 1, AT_LEAST, 32),
    R(GL_MAX_NAME_STACK_DEPTH, 1, AT_LEAST, 64),
    R(GL_MAX_LIST_NESTING, 1, AT_LEAST, 64),
    R(GL_MAX_EVAL_ORDER, 1, AT_LEAST, 8),
    R(GL_MAX_VIEWPORT_DIMS, 2, AT_LEAST, W),
    R(GL_MAX_ATTRIB_STACK_DEPTH, 1, AT_LEAST, 16),
    R(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, 1, AT_LEAST, 16),
    R(GL_MAX_ELEMENTS_INDICES, 1, AT_LEAST, 1),
    R(GL_MAX_ELEMENTS_VERTICES, 1, AT_LEAST, 1),
    R(GL_MAX_TEXTURE_UNITS, 1, AT_LEAST, 2),
    R(GL_AUX_BUFFERS, 1, AT_LEAST, 0),
    R(GL_ALIASED_POINT_SIZE_RANGE, 2, AT_LEAST, 1),
    R(GL_SMOOTH_POINT_SIZE_RANGE, 2, ANY, 0),
    R(GL_SMOOTH_POINT_SIZE_GRANULARITY, 1, ANY, 0),
    R(GL_ALIASED_LINE_WIDTH_RANGE, 2, AT_LEAST, 1),
    R(GL_SMOOTH_LINE_WIDTH_RANGE, 2, ANY, 0),
    R(GL_SMOOTH_LINE_WIDTH_GRANULARITY, 1, ANY, 0),
    R(GL_SAMPLE_BUFFERS, 1, AT_LEAST, 0),
    R(GL_SAMPLES, 1, AT_LEAST, 0),
    R(GL_NUM_COMPRESSED_TEXTURE_FORMATS, 1, AT_LEAST, 0),
    R(GL_RGBA_MODE, 1, EXACT, 1),
    R(GL_INDEX_MODE, 1, EXACT, 0),
    R(GL_DOUBLEBUFFER, 1, EXACT, 0),
    R(GL_STEREO, 1, EXACT, 0),
    /* 6.32 framebuffer sizes of this context */
    R(GL_RED_BITS, 1, EXACT, 8),
    R(GL_GREEN_BITS, 1, EXACT, 8),
    R(GL_BLUE_BITS, 1, EXACT, 8),
    R(GL_ALPHA_BITS, 1, EXACT, 8),
    R(GL_INDEX_BITS, 1, AT_LEAST, 0),
    R(GL_DEPTH_BITS, 1, AT_LEAST, 24),
    R(GL_STENCIL_BITS, 1, EXACT, 8),
    R(GL_ACCUM_RED_BITS, 1, EXACT, 0),
    R(GL_ACCUM_GREEN_BITS, 1, EXACT, 0),
    R(GL_ACCUM_BLUE_BITS, 1, EXACT, 0),
    R(GL_ACCUM_ALPHA_BITS, 1, EXACT, 0),
    /* 6.33 to 6.36 miscellaneous */
    R(GL_LIST_BASE, 1, EXACT, 0),
    R(GL_LIST_INDEX, 1, EXACT, 0),
    R(GL_LIST_MODE, 1, EXACT, 0),
    R(GL_ATTRIB_STACK_DEPTH, 1, EXACT, 0),
    R(GL_CLIENT_ATTRIB_STACK_DEPTH, 1, EXACT, 0),
    R(GL_NAME_STACK_DEPTH, 1, EXACT, 0),
    R(GL_RENDER_MODE, 1, EXACT, GL_RENDER),
    R(GL_SELECTION_BUFFER_SIZE, 1, EXACT, 0),
    R(GL_FEEDBACK_BUFFER_SIZE, 1, EXACT, 0),
    R(GL_FEEDBACK_BUFFER_TYPE, 1, EXACT, GL_2D),
};

/* How many values a glGet wrote: the first SENTINEL left in the buffer. */
static int written(const GLint *v)
{
    int n = 0;
    while (n < MAXV && v[n] != SENTINEL)
        n++;
    return n;
}

static void check_row(const struct row *r)
{
    GLint iv[MAXV];
    GLfloat fv[MAXV];
    GLdouble dv[MAXV];
    GLboolean bv[MAXV + 4];
    int i, ni, nf, nd, nb;

    for (i = 0; i < MAXV; i++) {
        iv[i] = SENTINEL;
        fv[i] = -12345.5f;
        dv[i] = -12345.5;
    }
    for (i = 0; i < MAXV + 4; i++)
        bv[i] = 0x5a;
    while (glGetError() != GL_NO_ERROR)
        ;
    glGetIntegerv(r->e, iv);
    glGetFloatv(r->e, fv);
    glGetDoublev(r->e, dv);
    glGetBooleanv(r->e, bv);
    if (glGetError() != GL_NO_ERROR) {
        h_expect(0, "%s: glGet* gave an error", r->name);
        return;
    }
    ni = written(iv);
    for (nf = 0; nf < MAXV && fv[nf] != -12345.5f; nf++)
        ;
    for (nd = 0; nd < MAXV && dv[nd] != -12345.5; nd++)
        ;
    for (nb = 0; nb < MAXV && bv[nb] != 0x5a; nb++)
        ;
    h_expect(ni == r->n && nf == r->n && nd == r->n && nb == r->n,
             "%s: %d values expected, got %d int, %d float, %d double, %d boolean",
             r->name, r->n, ni, nf, nd, nb);
    for (i = 0; i < r->n && i < nd; i++) {
        double want = r->kind == IDENTITY ? (i % 5 == 0) : r->v[r->kind == AT_LEAST ? 0 : i];
        if (r->kind == EXACT || r->kind == IDENTITY)
            h_expect(fabs(dv[i] - want) <= 1e-6, "%s[%d] = %g, expected %g", r->name, i, dv[i], want);
        else if (r->kind == AT_LEAST)
            h_expect(dv[i] >= want, "%s[%d] = %g, expected at least %g", r->name, i, dv[i], want);
        h_expect(fv[i] == (GLfloat)dv[i], "%s[%d]: glGetFloatv %g against glGetDoublev %g", r->name, i, fv[i], dv[i]);
        h_expect(bv[i] == (dv[i] != 0 ? GL_TRUE : GL_FALSE), "%s[%d]: glGetBooleanv %d for %g", r->name, i, bv[i], dv[i]);
    }
}

/* glGetIntegerv of a value that is not a colour, normal or depth. */
static void expect_int(GLenum e, const char *name, int i, GLint want)
{
    GLint v[MAXV];
    int k;
    for (k = 0; k < MAXV; k++)
        v[k] = SENTINEL;
    glGetIntegerv(e, v);
    h_expect(v[i] == want, "glGetIntegerv(%s)[%d] = %d, expected %d", name, i, v[i], want);
}

int main(void)
{
    size_t i;
    GLint v[MAXV];

    h_init(W, H);
    for (i = 0; i < sizeof rows / sizeof *rows; i++)
        check_row(&rows[i]);

    /* 6.1.2: colours and the like map [-1, 1] onto [INT_MIN, INT_MAX]
     * (((2^32 - 1) c - 1) / 2); 0 reads back as 0. */
    expect_int(GL_CURRENT_COLOR, "GL_CURRENT_COLOR", 0, INT_MAX);
    expect_int(GL_COLOR_CLEAR_VALUE, "GL_COLOR_CLEAR_VALUE", 0, 0);
    expect_int(GL_FOG_COLOR, "GL_FOG_COLOR", 3, 0);
    expect_int(GL_DEPTH_RANGE, "GL_DEPTH_RANGE", 0, 0);
    expect_int(GL_DEPTH_RANGE, "GL_DEPTH_RANGE", 1, INT_MAX);
    expect_int(GL_CURRENT_NORMAL, "GL_CURRENT_NORMAL", 0, 0);
    glNormal3f(0, -1, 0.5f);
    expect_int(GL_CURRENT_NORMAL, "GL_CURRENT_NORMAL", 1, INT_MIN);
    expect_int(GL_CURRENT_NORMAL, "GL_CURRENT_NORMAL", 2, 1073741823);
    /* Other state reads back rounded to the nearest integer. */
    glLineWidth(2.75f);
    expect_int(GL_LINE_WIDTH, "GL_LINE_WIDTH", 0, 3);
    glFogf(GL_FOG_END, 10.25f);
    expect_int(GL_FOG_END, "GL_FOG_END", 0, 10);
    glPolygonOffset(-1.75f, 0);
    expect_int(GL_POLYGON_OFFSET_FACTOR, "GL_POLYGON_OFFSET_FACTOR", 0, -2);
    h_expect_no_error("conversions");

    /* Names outside the tables: GL_INVALID_ENUM, nothing written. */
    for (i = 0; i < MAXV; i++)
        v[i] = SENTINEL;
    glGetIntegerv(GL_TRIANGLES, v);
    h_expect_error(GL_INVALID_ENUM, "glGetIntegerv(GL_TRIANGLES)");
    glGetIntegerv(GL_TEXTURE_WIDTH, v);
    h_expect_error(GL_INVALID_ENUM, "glGetIntegerv(GL_TEXTURE_WIDTH)");
    glGetIntegerv(0xFFFF, v);
    h_expect_error(GL_INVALID_ENUM, "glGetIntegerv(0xFFFF)");
    h_expect(written(v) == 0, "a rejected glGetIntegerv wrote %d values", written(v));

    /* glReadPixels of a (0, 1, 0, 1) clear into GL_BYTE, GL_SHORT, GL_INT. */
    {
        GLbyte b[4];
        GLshort s[4];
        GLint n[4];
        glClearColor(0, 1, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glReadPixels(3, 3, 1, 1, GL_RGBA, GL_BYTE, b);
        glReadPixels(3, 3, 1, 1, GL_RGBA, GL_SHORT, s);
        glReadPixels(3, 3, 1, 1, GL_RGBA, GL_INT, n);
        h_expect(b[0] == 0 && b[1] == 127 && b[2] == 0 && b[3] == 127, "GL_BYTE read %d %d %d %d", b[0], b[1], b[2], b[3]);
        h_expect(s[0] == 0 && s[1] == 32767 && s[2] == 0 && s[3] == 32767, "GL_SHORT read %d %d %d %d", s[0], s[1], s[2], s[3]);
        h_expect(n[0] == 0 && n[1] == INT_MAX && n[2] == 0 && n[3] == INT_MAX, "GL_INT read %d %d %d %d", n[0], n[1], n[2], n[3]);
        h_expect_no_error("glReadPixels into signed types");
    }
    return h_finish();
}
