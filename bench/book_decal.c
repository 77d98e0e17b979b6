/* Benchmark scene "book_decal": the Russian book's stencil-decal airplane,
 * stage 6 (ground, asphalt and stripes as stencilled decals, the blended
 * shadow), drawn by the C port's own code (c_tests/book/t_book_s2_decal.c,
 * included with its main renamed). */
#define main book_decal_port_main
#include "t_book_s2_decal.c"
#undef main
#undef W /* the port's fixed window size; the benchmark's is in scenes.h */
#undef H
#include "scenes.h"

void book_decal(int frame)
{
    static int ready;
    (void)frame;
    if (!ready) {
        init();
        ready = 1;
    }
    useStencil = 1;
    stage = 6;
    dataChoice = DCOLOR;
    glViewport(0, 0, W, H);
    glClear(GL_STENCIL_BUFFER_BIT); /* to 5, as init set: each frame alike */
    WMPaint();
}
