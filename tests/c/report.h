/* What the test programs print, one record per line: the error flag after a call, an
 * integer state with the error after reading it, and the image as a binary PPM (top row
 * first; OSMesa leaves the buffer bottom row first). Inline, so a program that uses only
 * some of them builds without warnings. */
#ifndef REPORT_H
#define REPORT_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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

/* Whether the extension string names `name` (a whole name, not a prefix of another). */
static inline int extension_named(const char *name) {
  const char *all = (const char *)glGetString(GL_EXTENSIONS);
  size_t n = strlen(name);
  for (const char *p = all; p && (p = strstr(p, name)) != NULL; p += n)
    if ((p == all || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return 1;
  return 0;
}

static inline void ints(const char *what, GLenum pname) {
  GLint v = -7;
  glGetIntegerv(pname, &v);
  printf("%-40s %d  err 0x%x\n", what, v, glGetError());
}

/* A new texture object bound to TEXTURE_2D, sampled NEAREST and applied with REPLACE. */
static inline GLuint replace_texture(void) {
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  return tex;
}

/* A replace_texture() over a window cleared to dark grey: the start of the programs that
 * draw a texture a panel. */
static inline GLuint replace_texture_panels(void) {
  GLuint tex = replace_texture();
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  return tex;
}

/* The square of the viewport, (-1, -1) to (1, 1) under identity matrices, with texture
 * coordinates (0, 0) to (1, 1): a texture drawn over a panel. */
static inline void textured_square(void) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(-1, -1);
  glTexCoord2f(1, 0);
  glVertex2f(1, -1);
  glTexCoord2f(1, 1);
  glVertex2f(1, 1);
  glTexCoord2f(0, 1);
  glVertex2f(-1, 1);
  glEnd();
}

/* The start of a drawing program: a context with 24 depth and 8 stencil bits made current
 * on a new w×h RGBA buffer (returned; NULL when that fails), with glOrtho(0, w, 0, h) so
 * that a unit is a pixel. */
static inline GLubyte *open_window(OSMesaContext *ctx, int w, int h) {
  *ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc((size_t)w * h, 4);
  if (!*ctx || !buf || !OSMesaMakeCurrent(*ctx, buf, GL_UNSIGNED_BYTE, w, h)) return NULL;
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, w, 0, h, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  return buf;
}

/* The end of a program: the image finished and written to `out`, the context and its
 * buffer freed. The exit status: 0, or 1 when the image could not be written. */
static inline int finish(const char *out, OSMesaContext ctx, GLubyte *buf, int w, int h) {
  glFinish();
  int written = write_ppm(out, buf, w, h);
  OSMesaDestroyContext(ctx);
  free(buf);
  return written ? 0 : 1;
}

#endif
