/* Benchmark scene "book_dino": the Persian book's reflected dinosaur with
 * the stencil on, drawn by the C port's own code (c_tests/book/
 * t_book_s0_dino.c, included here with its main renamed), turning a little
 * each frame. Built against Mesa's headers so the port opens no wgl
 * context: the benchmark's OSMesa context is current. */
#define main book_dino_port_main
#include "t_book_s0_dino.c"
#undef main
#undef W /* the port's fixed window size; the benchmark's is in scenes.h */
#undef H
#include "scenes.h"

void book_dino(int frame)
{
    static int ready;
    if (!ready) {
        initGL(); /* the lists, lights and projection, as the book */
        ready = 1;
    }
    useStencil = 1;
    angle = 20.0f + 4.0f * (frame % 10);
    glViewport(0, 0, W, H);
    redraw();
}
