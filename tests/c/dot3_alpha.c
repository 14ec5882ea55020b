/* DOT3_RGBA (GL 1.3's ARB_texture_env_dot3) writes the dot product to all four
 * components: the colour scaled by RGB_SCALE, the alpha by ALPHA_SCALE (GL 1.5 §3.8.13),
 * each clamped; COMBINE_ALPHA and its sources are ignored. Panels under each pair of
 * scales, and DOT3_RGB beside them (its alpha from COMBINE_ALPHA). Run on Mesa's OSMesa
 * and on fixedfunc's library, the printed lines must be the same and the images match.
 *
 * usage: dot3_alpha [out.ppm] */
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
  textured_square();
  glFinish();
  const GLubyte *p = buf + 4 * (4 * W + x + 4);
  printf("%-36s %3d %3d %3d %3d err 0x%x\n", what, p[0], p[1], p[2], p[3], glGetError());
}

static void scales(GLfloat rgb, GLfloat alpha) {
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, rgb);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, alpha);
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "dot3_alpha.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  const GLubyte texel[4] = {200, 60, 130, 90};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGBA);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PRIMARY_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_TEXTURE);
  glColor4f(0.8f, 0.3f, 0.6f, 0.35f);
  scales(1, 1);
  panel("DOT3_RGBA scales 1 1");
  scales(1, 2);
  panel("DOT3_RGBA ALPHA_SCALE 2");
  scales(4, 1);
  panel("DOT3_RGBA RGB_SCALE 4");
  scales(2, 4);
  panel("DOT3_RGBA RGB_SCALE 2 ALPHA_SCALE 4");
  glColor4f(0.6f, 0.5f, 0.5f, 1);
  scales(4, 2);
  panel("DOT3_RGBA small dot 4 2");
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGB);
  panel("DOT3_RGB small dot 4 2");
  glColor4f(0.8f, 0.3f, 0.6f, 0.35f);
  scales(1, 2);
  panel("DOT3_RGB ALPHA_SCALE 2");
  return finish(out, ctx, buf, W, H);
}
