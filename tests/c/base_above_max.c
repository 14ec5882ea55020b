/* TEXTURE_BASE_LEVEL above TEXTURE_MAX_LEVEL. Mesa's completeness check
 * (_mesa_test_texobj_completeness) calls that only mipmap-incomplete: a minifying filter
 * without mipmaps samples the base level, a mipmapped one finds the texture incomplete and
 * the unit off (the fragment keeps its colour). Level 0 is red, level 1 green, level 2
 * blue; each panel draws the texture under MODULATE over a white quad and prints its
 * centre.
 *
 * usage: base_above_max [out.ppm] */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 64
#define H 8

static GLubyte *buf;
static int panels;

static void panel(const char *what, GLint base, GLint max, GLenum min_filter) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, base);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, max);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min_filter);
  int x = panels++ * 8;
  glViewport(x, 0, 8, 8);
  textured_square();
  glFinish();
  const GLubyte *p = buf + 4 * (4 * W + x + 4);
  printf("%-40s %3d %3d %3d  err 0x%x\n", what, p[0], p[1], p[2], glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "base_above_max.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 3;
  static const GLubyte colours[3][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}};
  GLubyte texels[16 * 4];
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  for (int level = 0, size = 4; level < 3; level++, size /= 2) {
    for (int i = 0; i < size * size; i++)
      for (int c = 0; c < 4; c++) texels[4 * i + c] = colours[level][c];
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  panel("base 0 max 1000 NEAREST", 0, 1000, GL_NEAREST);
  panel("base 1 max 0 NEAREST", 1, 0, GL_NEAREST);
  panel("base 1 max 0 LINEAR", 1, 0, GL_LINEAR);
  panel("base 2 max 1 NEAREST", 2, 1, GL_NEAREST);
  panel("base 1 max 0 NEAREST_MIPMAP_NEAREST", 1, 0, GL_NEAREST_MIPMAP_NEAREST);
  panel("base 2 max 0 LINEAR_MIPMAP_LINEAR", 2, 0, GL_LINEAR_MIPMAP_LINEAR);
  panel("base 1 max 1 NEAREST_MIPMAP_NEAREST", 1, 1, GL_NEAREST_MIPMAP_NEAREST);
  return finish(out, ctx, buf, W, H);
}
