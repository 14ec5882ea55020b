/* A NaN or infinite texture coordinate at one vertex, as Mesa's OSMesa draws it: the
 * texture matrix is the identity, so no product mixes the coordinates (Mesa's program
 * leaves an identity matrix out, and so does the layer's), and only the non-finite one is
 * lost where it is interpolated. Two triangles over a 4x4 NEAREST texture with REPLACE:
 * s = NaN at one corner, then t = +Inf; then the same with a texture matrix that is not
 * the identity (a translation). Prints pixels of each.
 *
 * usage: nan_texcoords [out.ppm] */
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include "report.h"

#define W 64
#define H 64

static GLubyte *buf;

static void triangle(float x, float y, float s1, float t1) {
  glBegin(GL_TRIANGLES);
  glTexCoord2f(0, 0); glVertex2f(x + 2, y + 2);
  glTexCoord2f(s1, t1); glVertex2f(x + 30, y + 2);
  glTexCoord2f(0, 1); glVertex2f(x + 2, y + 30);
  glEnd();
}

static void pixels(const char *what, int x, int y) {
  static const int at[3][2] = {{3, 3}, {18, 3}, {3, 18}};
  printf("%-28s", what);
  for (int i = 0; i < 3; i++) {
    const GLubyte *p = buf + 4 * ((y + at[i][1]) * W + x + at[i][0]);
    printf("  %3d %3d %3d", p[0], p[1], p[2]);
  }
  printf("  err 0x%x\n", glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "nan_texcoords.ppm";
  OSMesaContext ctx;
  buf = open_window(&ctx, W, H);
  if (!buf) return 2;
  glClear(GL_COLOR_BUFFER_BIT);
  GLubyte texels[4 * 4 * 4];
  for (int i = 0; i < 16; i++) {
    texels[4 * i] = (GLubyte)(i * 16);
    texels[4 * i + 1] = (GLubyte)(255 - i * 16);
    texels[4 * i + 2] = (GLubyte)((i & 1) * 255);
    texels[4 * i + 3] = 255;
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);

  triangle(0, 0, NAN, 0);
  triangle(32, 0, 1, INFINITY);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.25f, 0, 0);
  glMatrixMode(GL_MODELVIEW);
  triangle(0, 32, 0.5f, 0);
  glFinish();
  pixels("s = NaN", 0, 0);
  pixels("t = +Inf", 32, 0);
  pixels("texture matrix translated", 0, 32);
  return finish(out, ctx, buf, W, H);
}
