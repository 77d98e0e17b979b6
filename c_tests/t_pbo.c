/* t_pbo: pixel buffer objects (ARB_pixel_buffer_object) and mapped buffer
 * ranges (ARB_map_buffer_range).
 *
 * - glTexImage2D and glTexSubImage2D read from the PIXEL_UNPACK_BUFFER at
 *   the offset passed as the pointer (with UNPACK_SKIP_PIXELS honoured);
 *   glGetTexImage into client memory gives the bytes back.
 * - glGetTexImage and glReadPixels write into the PIXEL_PACK_BUFFER at an
 *   offset; the bytes before it stay as they were.
 * - glDrawPixels, glPolygonStipple and glPixelMapfv read from the unpack
 *   buffer; glGetPolygonStipple and glGetPixelMapfv write to the pack buffer.
 * - An image reaching past the end of the store, or a mapped buffer, is
 *   INVALID_OPERATION and changes nothing.
 * - glMapBufferRange maps [offset, offset + length): writes land there;
 *   BUFFER_MAP_OFFSET / LENGTH / ACCESS_FLAGS report the mapping; with
 *   FLUSH_EXPLICIT, flushed writes are in the store after unmapping; the
 *   extension's INVALID_VALUE / INVALID_OPERATION cases.
 * - glPushClientAttrib(CLIENT_PIXEL_STORE_BIT) saves the pack and unpack
 *   buffer bindings with the pixel-store modes; the vertex-array bit does
 *   not; a buffer deleted since the push comes back unbound.
 */
#include "harness.h"
#include <stdint.h>
#include <string.h>

#define OFS(n) ((const void *)(uintptr_t)(n))
#define OFSW(n) ((void *)(uintptr_t)(n))

static void pbo_unpack(void)
{
    /* 2x2 RGBA texels at offset 16, one skipped pixel before each row's
     * first texel (ROW_LENGTH 3, SKIP_PIXELS 1). */
    unsigned char store[16 + 3 * 2 * 4];
    unsigned char expect[2 * 2 * 4], got[2 * 2 * 4];
    GLuint buf, tex;
    int i;
    for (i = 0; i < (int)sizeof store; i++)
        store[i] = (unsigned char)(i * 7 + 3);
    for (i = 0; i < 2; i++) {
        memcpy(expect + i * 8, store + 16 + i * 12 + 4, 8);
    }
    glGenBuffers(1, &buf);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buf);
    glBufferData(GL_PIXEL_UNPACK_BUFFER, sizeof store, store, GL_STREAM_DRAW);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 3);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, OFS(16));
    h_expect_no_error("glTexImage2D from a pixel unpack buffer");
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    memset(got, 0, sizeof got);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, got);
    h_expect(memcmp(got, expect, sizeof got) == 0, "texels from the unpack buffer: %d %d %d %d, want %d %d %d %d",
             got[0], got[1], got[2], got[3], expect[0], expect[1], expect[2], expect[3]);

    /* glTexSubImage2D of one texel from offset 4. */
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buf);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, OFS(4));
    h_expect_no_error("glTexSubImage2D from a pixel unpack buffer");
    /* Past the end of the store: 2x2 RGBA (16 bytes) at offset 24 of 40. */
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, OFS(sizeof store - 15));
    h_expect_error(GL_INVALID_OPERATION, "glTexSubImage2D past the end of the unpack buffer");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, OFS(sizeof store - 15));
    h_expect_error(GL_INVALID_OPERATION, "glTexImage2D past the end of the unpack buffer");
    /* Mapped: INVALID_OPERATION. */
    glMapBuffer(GL_PIXEL_UNPACK_BUFFER, GL_READ_ONLY);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, OFS(0));
    h_expect_error(GL_INVALID_OPERATION, "glTexSubImage2D from a mapped buffer");
    glUnmapBuffer(GL_PIXEL_UNPACK_BUFFER);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    memcpy(expect + 12, store + 4, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, got);
    h_expect(memcmp(got, expect, sizeof got) == 0, "after the sub-image (and the failed ones): texel 3 = %d %d %d %d, want %d %d %d %d",
             got[12], got[13], got[14], got[15], expect[12], expect[13], expect[14], expect[15]);

    /* glGetTexImage into a pack buffer at offset 8. */
    {
        unsigned char back[8 + 16];
        GLuint pb;
        glGenBuffers(1, &pb);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, pb);
        memset(back, 0xAB, sizeof back);
        glBufferData(GL_PIXEL_PACK_BUFFER, sizeof back, back, GL_STREAM_READ);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, OFSW(8));
        h_expect_no_error("glGetTexImage into a pixel pack buffer");
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, OFSW(9));
        h_expect_error(GL_INVALID_OPERATION, "glGetTexImage past the end of the pack buffer");
        memset(back, 0, sizeof back);
        glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 0, sizeof back, back);
        h_expect(back[0] == 0xAB && back[7] == 0xAB, "bytes before the offset kept: %d %d", back[0], back[7]);
        h_expect(memcmp(back + 8, expect, 16) == 0, "glGetTexImage into the pack buffer: %d %d %d %d", back[8], back[9], back[10], back[11]);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        glDeleteBuffers(1, &pb);
    }
    glDeleteTextures(1, &tex);
    glDeleteBuffers(1, &buf);
}

static void pbo_pixels(void)
{
    static const unsigned char img[4 + 2 * 2 * 4] = {0, 0, 0, 0, 255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    unsigned char back[4 + 16];
    GLuint ub, pb;
    GLint binding = -1;
    glGenBuffers(1, &ub);
    glGenBuffers(1, &pb);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, ub);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, pb);
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &binding);
    h_expect(binding == (GLint)ub, "PIXEL_UNPACK_BUFFER_BINDING %d", binding);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &binding);
    h_expect(binding == (GLint)pb, "PIXEL_PACK_BUFFER_BINDING %d", binding);
    glBufferData(GL_PIXEL_UNPACK_BUFFER, sizeof img, img, GL_STATIC_DRAW);
    glBufferData(GL_PIXEL_PACK_BUFFER, sizeof back, NULL, GL_STREAM_READ);

    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glWindowPos2i(3, 3);
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, OFS(4));
    h_expect_no_error("glDrawPixels from a pixel unpack buffer");
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, OFS(5));
    h_expect_error(GL_INVALID_OPERATION, "glDrawPixels past the end of the unpack buffer");
    glReadPixels(3, 3, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, OFSW(4));
    h_expect_no_error("glReadPixels into a pixel pack buffer");
    glReadPixels(3, 3, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, OFSW(5));
    h_expect_error(GL_INVALID_OPERATION, "glReadPixels past the end of the pack buffer");
    {
        const unsigned char *p = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 4, 16, GL_MAP_READ_BIT);
        h_expect(p != NULL, "glMapBufferRange for reading");
        if (p)
            h_expect(memcmp(p, img + 4, 16) == 0, "drawn and read back through buffers: %d %d %d %d / %d %d %d %d",
                     p[0], p[1], p[2], p[3], p[12], p[13], p[14], p[15]);
        glReadPixels(3, 3, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, OFSW(4));
        h_expect_error(GL_INVALID_OPERATION, "glReadPixels into a mapped buffer");
        glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
    }
    /* (glReadPixels into client memory needs the pack buffer unbound.) */
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    h_expect_pixel(4, 4, 255, 255, 255, 255, 0, "glDrawPixels' top right pixel");
    glBindBuffer(GL_PIXEL_PACK_BUFFER, pb);

    /* Polygon stipple in, out; pixel map in, out. */
    {
        unsigned char pattern[128], out[128];
        GLfloat map[2] = {0.25f, 0.75f}, mout[2] = {0, 0};
        int i;
        for (i = 0; i < 128; i++)
            pattern[i] = (unsigned char)(i * 37 + 1);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glBufferData(GL_PIXEL_UNPACK_BUFFER, 256, NULL, GL_STATIC_DRAW);
        glBufferSubData(GL_PIXEL_UNPACK_BUFFER, 100, 128, pattern);
        glBufferSubData(GL_PIXEL_UNPACK_BUFFER, 8, sizeof map, map);
        glPolygonStipple(OFS(100));
        h_expect_no_error("glPolygonStipple from a pixel unpack buffer");
        glPolygonStipple(OFS(129));
        h_expect_error(GL_INVALID_OPERATION, "glPolygonStipple past the end");
        glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, OFS(8));
        h_expect_no_error("glPixelMapfv from a pixel unpack buffer");
        glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, OFS(252));
        h_expect_error(GL_INVALID_OPERATION, "glPixelMapfv past the end");
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        glBufferData(GL_PIXEL_PACK_BUFFER, 256, NULL, GL_STREAM_READ);
        glGetPolygonStipple(OFSW(64));
        glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, OFSW(200));
        h_expect_no_error("glGetPolygonStipple / glGetPixelMapfv into a pixel pack buffer");
        glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, OFSW(250));
        h_expect_error(GL_INVALID_OPERATION, "glGetPixelMapfv past the end");
        glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 64, 128, out);
        glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 200, sizeof mout, mout);
        h_expect(memcmp(out, pattern, 128) == 0, "stipple round trip: byte 0 %d want %d, byte 127 %d want %d", out[0], pattern[0], out[127], pattern[127]);
        h_expect(mout[0] == 0.25f && mout[1] == 0.75f, "pixel map round trip %g %g", mout[0], mout[1]);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glDeleteBuffers(1, &ub);
    glDeleteBuffers(1, &pb);
}

static void map_range(void)
{
    unsigned char data[32], got[32];
    GLuint b;
    GLint v;
    void *ptr = NULL;
    unsigned char *p;
    int i;
    for (i = 0; i < 32; i++)
        data[i] = (unsigned char)i;
    glGenBuffers(1, &b);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBufferData(GL_ARRAY_BUFFER, 32, data, GL_STATIC_DRAW);

    /* Write 8 bytes at 4, invalidating the range. */
    p = glMapBufferRange(GL_ARRAY_BUFFER, 4, 8, GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT);
    h_expect_no_error("glMapBufferRange(WRITE | INVALIDATE_RANGE)");
    h_expect(p != NULL, "mapped pointer");
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_OFFSET, &v);
    h_expect(v == 4, "BUFFER_MAP_OFFSET %d", v);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_LENGTH, &v);
    h_expect(v == 8, "BUFFER_MAP_LENGTH %d", v);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS_FLAGS, &v);
    h_expect(v == (GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT), "BUFFER_ACCESS_FLAGS %d", v);
    glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &ptr);
    h_expect(ptr == p, "BUFFER_MAP_POINTER is the range's start");
    glMapBufferRange(GL_ARRAY_BUFFER, 0, 4, GL_MAP_READ_BIT);
    h_expect_error(GL_INVALID_OPERATION, "mapping a mapped buffer");
    glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, 4);
    h_expect_error(GL_INVALID_OPERATION, "flushing a mapping without FLUSH_EXPLICIT");
    if (p)
        for (i = 0; i < 8; i++)
            p[i] = (unsigned char)(200 + i);
    h_expect(glUnmapBuffer(GL_ARRAY_BUFFER) == GL_TRUE, "unmap");
    for (i = 0; i < 8; i++)
        data[4 + i] = (unsigned char)(200 + i);
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, 32, got);
    h_expect(memcmp(got, data, 32) == 0, "writes through the range: byte 3 %d, 4 %d, 11 %d, 12 %d", got[3], got[4], got[11], got[12]);

    /* FLUSH_EXPLICIT: write 4 bytes at 20 through a mapping of [16, 32), flush them. */
    p = glMapBufferRange(GL_ARRAY_BUFFER, 16, 16, GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT);
    h_expect(p != NULL, "glMapBufferRange(WRITE | FLUSH_EXPLICIT)");
    if (p)
        for (i = 0; i < 4; i++)
            p[4 + i] = (unsigned char)(100 + i);
    glFlushMappedBufferRange(GL_ARRAY_BUFFER, 4, 4);
    h_expect_no_error("glFlushMappedBufferRange");
    glFlushMappedBufferRange(GL_ARRAY_BUFFER, 8, 9);
    h_expect_error(GL_INVALID_VALUE, "flushing past the mapped range");
    glFlushMappedBufferRange(GL_ARRAY_BUFFER, -1, 2);
    h_expect_error(GL_INVALID_VALUE, "flushing at a negative offset");
    glUnmapBuffer(GL_ARRAY_BUFFER);
    for (i = 0; i < 4; i++)
        data[20 + i] = (unsigned char)(100 + i);
    glGetBufferSubData(GL_ARRAY_BUFFER, 16, 8, got);
    h_expect(memcmp(got, data + 16, 8) == 0, "flushed writes: %d %d %d %d %d", got[3], got[4], got[5], got[6], got[7]);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED, &v);
    h_expect(v == 0, "unmapped");

    /* The extension's errors. */
    glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, 4);
    h_expect_error(GL_INVALID_OPERATION, "flushing an unmapped buffer");
    h_expect(glMapBufferRange(GL_ARRAY_BUFFER, 0, 4, GL_MAP_READ_BIT | GL_MAP_INVALIDATE_RANGE_BIT) == NULL, "READ | INVALIDATE maps nothing");
    h_expect_error(GL_INVALID_OPERATION, "READ | INVALIDATE_RANGE");
    glMapBufferRange(GL_ARRAY_BUFFER, 0, 4, GL_MAP_READ_BIT | GL_MAP_FLUSH_EXPLICIT_BIT);
    h_expect_error(GL_INVALID_OPERATION, "FLUSH_EXPLICIT without WRITE");
    glMapBufferRange(GL_ARRAY_BUFFER, 0, 4, GL_MAP_INVALIDATE_BUFFER_BIT);
    h_expect_error(GL_INVALID_OPERATION, "neither READ nor WRITE");
    glMapBufferRange(GL_ARRAY_BUFFER, 30, 4, GL_MAP_READ_BIT);
    h_expect_error(GL_INVALID_VALUE, "range past the end");
    glMapBufferRange(GL_ARRAY_BUFFER, -1, 4, GL_MAP_READ_BIT);
    h_expect_error(GL_INVALID_VALUE, "negative offset");
    glMapBufferRange(GL_ARRAY_BUFFER, 0, 4, GL_MAP_READ_BIT | 0x100);
    h_expect_error(GL_INVALID_VALUE, "unknown access bit");
    glMapBufferRange(0x1234, 0, 4, GL_MAP_READ_BIT);
    h_expect_error(GL_INVALID_ENUM, "bad target");
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glMapBufferRange(GL_ARRAY_BUFFER, 0, 4, GL_MAP_READ_BIT);
    h_expect_error(GL_INVALID_OPERATION, "no buffer bound");
    glDeleteBuffers(1, &b);
}

static GLint binding(GLenum pname)
{
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
}

static void client_attrib(void)
{
    GLuint b[3];
    glGenBuffers(3, b);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, b[0]);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, b[1]);
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, b[2]);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPopClientAttrib();
    h_expect(binding(GL_PIXEL_PACK_BUFFER_BINDING) == (GLint)b[0] && binding(GL_PIXEL_UNPACK_BUFFER_BINDING) == (GLint)b[1],
             "pixel-store pop restores the pack/unpack bindings: %d %d, want %u %u",
             binding(GL_PIXEL_PACK_BUFFER_BINDING), binding(GL_PIXEL_UNPACK_BUFFER_BINDING), b[0], b[1]);

    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, b[2]);
    glPopClientAttrib();
    h_expect(binding(GL_PIXEL_PACK_BUFFER_BINDING) == (GLint)b[2],
             "vertex-array pop leaves the pack binding: %d, want %u", binding(GL_PIXEL_PACK_BUFFER_BINDING), b[2]);

    glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
    glDeleteBuffers(1, &b[2]);
    glPopClientAttrib();
    h_expect(binding(GL_PIXEL_PACK_BUFFER_BINDING) == 0 && binding(GL_PIXEL_UNPACK_BUFFER_BINDING) == (GLint)b[1],
             "a buffer deleted since the push comes back unbound: %d %d, want 0 %u",
             binding(GL_PIXEL_PACK_BUFFER_BINDING), binding(GL_PIXEL_UNPACK_BUFFER_BINDING), b[1]);
    h_expect_no_error("client attrib with pixel buffers");
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glDeleteBuffers(2, b);
}

int main(void)
{
    h_init(8, 8);
    pbo_unpack();
    pbo_pixels();
    map_range();
    client_attrib();
    return h_finish();
}
