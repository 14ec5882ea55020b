/* Which texture a unit samples when several targets are enabled and the highest is not
 * complete, as Mesa's OSMesa draws it: the highest-priority enabled target whose texture
 * is complete (cube map, 3D, 2D, 1D; Mesa's _mesa_update_texture_unit_state), where GL 1.5
 * §3.8.15 would take the highest enabled target alone and turn the unit off. Four squares
 * over a blue colour with REPLACE: 2D green with an empty cube map enabled, with an empty
 * 3D texture enabled, an incomplete 2D (a mipmap filter, one level) over a complete red
 * 1D of two texels, and both incomplete (the unit off: blue). Prints the centre pixel of each.
 *
 * usage: target_fallback [out.ppm] */
#include <GL/osmesa.h>
#include <stdio.h>
#include "report.h"

#define W 64
#define H 16

static GLubyte *buf;

static void square(const char *what, float x) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0); glVertex2f(x, 0);
  glTexCoord2f(1, 0); glVertex2f(x + 12, 0);
  glTexCoord2f(1, 1); glVertex2f(x + 12, 12);
  glTexCoord2f(0, 1); glVertex2f(x, 12);
  glEnd();
  glFinish();
  const GLubyte *p = buf + 4 * (6 * W + (int)x + 6);
  printf("%-40s %3d %3d %3d  err 0x%x\n", what, p[0], p[1], p[2], glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "target_fallback.ppm";
  OSMesaContext ctx;
  buf = open_window(&ctx, W, H);
  if (!buf) return 2;
  glClear(GL_COLOR_BUFFER_BIT);

  static const GLubyte green[4] = {0, 255, 0, 255}, red[8] = {255, 0, 0, 255, 255, 0, 0, 255};
  static const GLubyte green2x2[16] = {0, 255, 0, 255, 0, 255, 0, 255,
                                       0, 255, 0, 255, 0, 255, 0, 255};
  GLuint tex[2];
  glGenTextures(2, tex);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glColor3f(0, 0, 1);
  glEnable(GL_TEXTURE_2D);

  glEnable(GL_TEXTURE_CUBE_MAP);
  square("2D, an empty cube map enabled", 0);
  glDisable(GL_TEXTURE_CUBE_MAP);
  glEnable(GL_TEXTURE_3D);
  square("2D, an empty 3D texture enabled", 16);
  glDisable(GL_TEXTURE_3D);

  glBindTexture(GL_TEXTURE_1D, tex[1]);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, red);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_1D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, green2x2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  square("2D incomplete over a complete 1D", 32);

  /* Two texels and one level under a mipmap filter: incomplete. */
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  square("2D and 1D incomplete: the unit off", 48);
  return finish(out, ctx, buf, W, H);
}
