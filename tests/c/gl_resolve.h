/* How a test program reaches GL: linked directly (the default), or, with
 * -DRESOLVE_WITH_PROC_ADDRESS, through OSMesaGetProcAddress — each GL function the
 * program uses is listed once in GL_FUNCTIONS(X) and becomes a pointer of that name. */
#ifndef GL_RESOLVE_H
#define GL_RESOLVE_H

#include <stdio.h>
#include <stdlib.h>
#include <GL/osmesa.h>

#ifdef RESOLVE_WITH_PROC_ADDRESS
#define DECLARE_POINTER(ret, name, params) static ret (*p_##name) params;
GL_FUNCTIONS(DECLARE_POINTER)
#define RESOLVE_POINTER(ret, name, params)                                         \
  p_##name = (ret(*) params)(void (*)(void))OSMesaGetProcAddress(#name);          \
  if (!p_##name) {                                                                  \
    fprintf(stderr, "OSMesaGetProcAddress(\"%s\") returned NULL\n", #name);         \
    exit(2);                                                                        \
  }
static inline void resolve_gl(void) { GL_FUNCTIONS(RESOLVE_POINTER) }
#else
static inline void resolve_gl(void) {}
#endif

/* Writes the RGBA buffer (bottom row first, as OSMesa leaves it) as a binary PPM, top
 * row first. */
static int write_ppm(const char *path, const GLubyte *rgba, int w, int h) {
  FILE *f = fopen(path, "wb");
  if (!f) return 0;
  fprintf(f, "P6\n%d %d\n255\n", w, h);
  for (int y = h - 1; y >= 0; y--)
    for (int x = 0; x < w; x++) fwrite(rgba + 4 * (y * w + x), 1, 3, f);
  return fclose(f) == 0;
}

#endif
