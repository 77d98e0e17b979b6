/* Shared between the benchmark's scene files (bench/scenes.c has main). */
#ifndef SOFTGL_BENCH_SCENES_H
#define SOFTGL_BENCH_SCENES_H

extern int W, H;

/* Clear to (r, g, b), depth test off, identity matrices. */
void clear_2d(float r, float g, float b);
/* The projection every 3D scene uses: a frustum of the window's aspect. */
void perspective(void);
/* One smooth-coloured sphere of triangle strips. */
void sphere(int stacks, int slices);
/* 5x5 spheres; 25 * 4 * detail^2 triangles. */
void spheres(int frame, int detail);

/* bench/scenes_features.c: the scenes of the GL features beyond the
 * basic ones; each returns 0 for a name it does not know. */
int feature_scene(const char *scene, int frame);

/* bench/book_*.c: the book programs' drawing code (c_tests/book ports). */
void book_dino(int frame);
void book_decal(int frame);
void book_winding(int frame);

#endif
