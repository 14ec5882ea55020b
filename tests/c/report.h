/* What the test programs print, one record per line: the error flag after a call, an
 * integer state with the error after reading it, and the image as a binary PPM (top row
 * first; OSMesa leaves the buffer bottom row first). Inline, so a program that uses only
 * some of them builds without warnings. */
#ifndef REPORT_H
#define REPORT_H

#include <stdio.h>
#include <GL/osmesa.h>

static inline int write_ppm(const char *path, const GLubyte *rgba, int w, int h) {
  FILE *f = fopen(path, "wb");
  if (!f) return 0;
  fprintf(f, "P6\n%d %d\n255\n", w, h);
  for (int y = h - 1; y >= 0; y--)
    for (int x = 0; x < w; x++) fwrite(rgba + 4 * (y * w + x), 1, 3, f);
  return fclose(f) == 0;
}

static inline void err(const char *what) { printf("%-40s err 0x%x\n", what, glGetError()); }

static inline void ints(const char *what, GLenum pname) {
  GLint v = -7;
  glGetIntegerv(pname, &v);
  printf("%-40s %d  err 0x%x\n", what, v, glGetError());
}

#endif
