/* GENERATE_MIPMAP (GL 1.4) set after the base level exists derives nothing at once (level
 * 1 stays unspecified); the next change to the base level — glTexSubImage1D/2D/3D,
 * glCopyTexSubImage2D, a cube face's glTexImage2D — derives every level from it. The
 * levels are read back and a mipmapped 2D texture is drawn minified. Run on Mesa's OSMesa
 * and on fixedfunc's library, the printed lines must be the same and the images match.
 *
 * usage: mipmaps_generated_late [out.ppm] */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"
#define W 16
#define H 16

static void level(const char *what, GLenum target, int l) {
  GLint w = -1;
  static GLubyte g[16 * 16 * 4];
  memset(g, 0xee, sizeof g);
  glGetTexLevelParameteriv(target, l, GL_TEXTURE_WIDTH, &w);
  glGetTexImage(target, l, GL_RGBA, GL_UNSIGNED_BYTE, g);
  printf("%-28s level %d width %d: %d %d %d %d err 0x%x\n", what, l, w, g[0], g[1], g[2],
         g[3], glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "mipmaps_generated_late.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  GLubyte t1[8 * 4];
  for (int i = 0; i < 8; i++) {
    t1[4 * i] = (GLubyte)(i * 32);
    t1[4 * i + 1] = (GLubyte)(255 - i * 32);
    t1[4 * i + 2] = (GLubyte)((i & 1) * 255);
    t1[4 * i + 3] = (GLubyte)(128 + i * 16);
  }
  glBindTexture(GL_TEXTURE_1D, 1);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, t1);
  glTexParameteri(GL_TEXTURE_1D, GL_GENERATE_MIPMAP, GL_TRUE);
  level("1D, the flag set", GL_TEXTURE_1D, 1);
  glTexSubImage1D(GL_TEXTURE_1D, 0, 2, 3, GL_RGBA, GL_UNSIGNED_BYTE, t1);
  for (int l = 1; l < 4; l++) level("1D after a sub-image", GL_TEXTURE_1D, l);

  GLubyte t2[16 * 16 * 4];
  for (int i = 0; i < 16 * 16; i++) {
    t2[4 * i] = (GLubyte)(i % 16 * 16);
    t2[4 * i + 1] = (GLubyte)(i / 16 * 16);
    t2[4 * i + 2] = 0;
    t2[4 * i + 3] = 255;
  }
  glBindTexture(GL_TEXTURE_2D, 2);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, t2);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  level("2D, the flag set", GL_TEXTURE_2D, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, t2 + 200);
  for (int l = 1; l < 5; l++) level("2D after a sub-image", GL_TEXTURE_2D, l);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 16, 16);
  level("2D after a copy", GL_TEXTURE_2D, 3);

  static GLubyte t3[4 * 4 * 4 * 4];
  for (int i = 0; i < 64; i++) {
    t3[4 * i] = (GLubyte)(i * 4);
    t3[4 * i + 1] = (GLubyte)(255 - i * 4);
    t3[4 * i + 3] = 255;
  }
  glBindTexture(GL_TEXTURE_3D, 3);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, t3);
  glTexParameteri(GL_TEXTURE_3D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, t3 + 100);
  level("3D after a sub-image", GL_TEXTURE_3D, 2);

  glBindTexture(GL_TEXTURE_2D, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, t2);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, t2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glViewport(0, 0, 4, 4);
  textured_square();
  glFinish();
  printf("level 2 drawn %d %d %d %d err 0x%x\n", buf[4 * (W + 1)], buf[4 * (W + 1) + 1],
         buf[4 * (W + 1) + 2], buf[4 * (W + 1) + 3], glGetError());
  return finish(out, ctx, buf, W, H);
}
