/* Benchmark scene "book_winding": the Persian book's winding-rule panels,
 * tessellated again every frame (the rule cycling through all five, as the
 * book's key does) into display lists and drawn, by the C port's own code
 * (c_tests/book/t_book_s0_tesswind.c, included with its main renamed). */
#define main book_winding_port_main
#include "t_book_s0_tesswind.c"
#undef main
#undef W /* the port's fixed window size; the benchmark's is in scenes.h */
#undef H
#include "scenes.h"

void book_winding(int frame)
{
    static const GLdouble rules[5] = {GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO,
        GLU_TESS_WINDING_POSITIVE, GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO};
    if (!tobj)
        init_gl();
    reshape(W, H);
    ncombined = 0;
    make_new_lists(GLU_TESS_WINDING_RULE, rules[frame % 5]);
    display();
}
