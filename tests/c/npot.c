/* ARB_texture_non_power_of_two as programs of the mid-2000s used it: the extension
 * checked in the extension string, then textures of any size — a 7×5 texture with its
 * chain 3×2 and 1×1 given level by level, the same chain made by GENERATE_MIPMAP, REPEAT
 * across a non-power-of-two width, CLAMP and CLAMP_TO_EDGE, a 13×11 glCopyTexImage2D, a
 * proxy, and the 1D, 3D and cube-map targets (a cube face must still be square). Each
 * drawn into a panel minified and magnified. Run on Mesa's OSMesa and on fixedfunc's
 * library, the printed lines must be the same and the images match.
 *
 * usage: npot [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 96
#define H 64

/* A square of window units (x0, y0)–(x1, y1) with texture coordinates 0 to `s`. */
static void quad(float x0, float y0, float x1, float y1, float s) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(x0, y0);
  glTexCoord2f(s, 0);
  glVertex2f(x1, y0);
  glTexCoord2f(s, s);
  glVertex2f(x1, y1);
  glTexCoord2f(0, s);
  glVertex2f(x0, y1);
  glEnd();
}

static void level_size(const char *what, GLenum target, GLint level) {
  GLint w = -7, h = -7;
  glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(target, level, GL_TEXTURE_HEIGHT, &h);
  printf("%-28s %d x %d err 0x%x\n", what, w, h, glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "npot.ppm";
  OSMesaContext ctx;
  GLubyte *buf = open_window(&ctx, W, H); /* glOrtho(0, W, 0, H): a unit is a pixel */
  if (!buf) return 1;
  printf("extension named %d\n", extension_named("GL_ARB_texture_non_power_of_two"));

  static GLubyte base[7 * 5 * 4], level1[3 * 2 * 4];
  static const GLubyte level2[4] = {10, 200, 90, 255};
  for (int i = 0; i < (int)sizeof base; i++) base[i] = (GLubyte)(i * 7 + 13);
  for (int i = 0; i < (int)sizeof level1; i++) level1[i] = (GLubyte)(255 - i * 9);
  GLuint tex[3];
  glGenTextures(3, tex);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  /* A chain given level by level: each level floor(half) of the one above. */
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 7, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, base);
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 3, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, level1);
  glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, level2);
  err("7x5 chain");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  quad(0, 0, 30, 30, 1);
  quad(32, 0, 40, 8, 1);
  quad(42, 0, 45, 3, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  quad(0, 32, 30, 62, 2.5f); /* REPEAT across 7 texels */

  /* The same chain generated. */
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 7, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, base);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  quad(48, 0, 58, 10, 1);
  quad(60, 0, 64, 4, 1);
  quad(66, 0, 67, 1, 1);
  level_size("generated level 1", GL_TEXTURE_2D, 1);
  level_size("generated level 2", GL_TEXTURE_2D, 2);

  /* Clamped both ways, then a copy of the window's corner. */
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, base);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
  quad(34, 32, 64, 62, 1.7f);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 13, 11, 0);
  err("13x11 glCopyTexImage2D");
  level_size("copied", GL_TEXTURE_2D, 0);
  quad(66, 32, 94, 62, 1);

  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 1000, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  level_size("proxy 1000x3", GL_PROXY_TEXTURE_2D, 0);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 7, 0, GL_RGBA, GL_UNSIGNED_BYTE, base);
  err("1D of 7");
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 3, 5, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, base);
  err("3D of 3x5x1");
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 3, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               base);
  err("cube face 3x3");
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 3, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               base);
  err("cube face 3x5");
  glFinish();
  printf("draw err 0x%x\n", glGetError());
  return finish(out, ctx, buf, W, H);
}
