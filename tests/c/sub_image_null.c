/* glTexSubImage1D/2D/3D with a NULL pointer: GL does not refuse it; Mesa checks the call as
 * any other (a region outside the level INVALID_VALUE, a level never specified
 * INVALID_OPERATION, a bad format INVALID_ENUM) and, when it passes, stores nothing — the
 * texels read back unchanged. Empty regions from a real array pass too. Run on Mesa's
 * OSMesa and on fixedfunc's library, the printed lines must be the same and the images
 * match.
 *
 * usage: sub_image_null [out.ppm] */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"
#define W 16
#define H 16

static void texels(const char *what, GLenum target) {
  GLubyte t[4 * 4 * 4 * 4];
  memset(t, 0xee, sizeof t);
  glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  printf("%-40s", what);
  for (int i = 0; i < 16; i += 4) printf(" %d", t[i]);
  printf(" err 0x%x\n", glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "sub_image_null.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  GLubyte s[4 * 4 * 4 * 4];
  for (unsigned i = 0; i < sizeof s; i++) s[i] = (GLubyte)(i * 7);
  replace_texture_panels();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, s);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("2D 2x2 from NULL");
  texels("2D texels", GL_TEXTURE_2D);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("2D 0x0 from NULL");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 3, GL_RGBA, GL_UNSIGNED_BYTE, s);
  err("2D 0x3 from an array");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 3, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("2D outside the level from NULL");
  glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("2D missing level from NULL");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_BITMAP, NULL);
  err("2D BITMAP type from NULL");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
  err("2D depth pixels from NULL");
  glTexSubImage1D(GL_TEXTURE_1D, 0, 0, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("1D without a level from NULL");
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, s);
  glTexSubImage1D(GL_TEXTURE_1D, 0, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("1D 2 from NULL");
  texels("1D texels", GL_TEXTURE_1D);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, s);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 1, 2, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("3D 2x2x1 from NULL");
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 1, 2, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("3D deeper than the level from NULL");
  texels("3D texels", GL_TEXTURE_3D);
  glNewList(1, GL_COMPILE);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glEndList();
  glCallList(1);
  err("2D from NULL in a display list");
  texels("2D texels after the list", GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_2D);
  textured_square();
  err("drawn");
  return finish(out, ctx, buf, W, H);
}
