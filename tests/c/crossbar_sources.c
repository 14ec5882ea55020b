/* ARB_texture_env_crossbar: a combine source naming another unit (TEXTUREn) reads that
 * unit's texel. When that unit is disabled, or its texture incomplete, the result is
 * undefined by the spec; Mesa reads (0, 0, 0, 0). Panels read an enabled unit, a disabled
 * one, an incomplete one, a unit with nothing bound, and a unit that only a 1D texture
 * enables. Run on Mesa's OSMesa and on fixedfunc's library, the printed lines must be the
 * same and the images match.
 *
 * usage: crossbar_sources [out.ppm] */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 64
#define H 8
static GLubyte *buf;
static int panels;

static void panel(const char *what) {
  int x = panels * 8;
  panels++;
  glViewport(x, 0, 8, 8);
  glBegin(GL_QUADS);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEnd();
  glFinish();
  const GLubyte *p = buf + 4 * (4 * W + x + 4);
  printf("%-36s %3d %3d %3d %3d err 0x%x\n", what, p[0], p[1], p[2], p[3], glGetError());
}

/* Unit u: 2D texture 10 + u of one texel, NEAREST. */
static void texel_on(int u, const GLubyte *c) {
  glActiveTexture(GL_TEXTURE0 + u);
  glBindTexture(GL_TEXTURE_2D, 10 + u);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, c);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
}

/* The active unit's combine: REPLACE of `source`, colour and alpha. */
static void replace_with(GLenum source) {
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_REPLACE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, source);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, source);
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "crossbar_sources.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  const GLubyte c0[4] = {200, 60, 130, 90}, c1[4] = {40, 220, 170, 230},
                c2[4] = {100, 150, 20, 60};
  texel_on(0, c0);
  texel_on(1, c1);
  texel_on(2, c2);
  glColor4f(0.8f, 0.3f, 0.6f, 0.35f);
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_TEXTURE_2D);
  replace_with(GL_TEXTURE1);
  glActiveTexture(GL_TEXTURE1);
  glEnable(GL_TEXTURE_2D);
  replace_with(GL_PREVIOUS);
  panel("TEXTURE1 enabled");
  glDisable(GL_TEXTURE_2D);
  panel("TEXTURE1 disabled");
  glEnable(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  panel("TEXTURE1 incomplete");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glDisable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE2);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  panel("TEXTURE1 disabled, unit 2 MODULATE");
  glDisable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);
  replace_with(GL_TEXTURE3);
  panel("TEXTURE3 with nothing bound");
  replace_with(GL_TEXTURE2);
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_1D, 20);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, c1);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_1D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  panel("TEXTURE2 enabled by a 1D texture");
  glDisable(GL_TEXTURE_1D);
  panel("TEXTURE2 disabled, 2D bound");
  return finish(out, ctx, buf, W, H);
}
