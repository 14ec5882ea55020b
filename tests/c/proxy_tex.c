/* The proxy targets of glTexImage1D and glTexImage2D (GL 1.5 §3.8.11): PROXY_TEXTURE_1D,
 * PROXY_TEXTURE_2D and PROXY_TEXTURE_CUBE_MAP. An image that fits specifies the proxy's
 * level, which glGetTexLevelParameter answers (width, height, internal format as named,
 * component sizes); one too large clears it (every answer 0, the internal format RGBA)
 * without an error; the argument and format errors are a real image's, but a proxy may
 * have a border of 1 (its sizes include it), as GL 1.5 §3.8.1 allows. A proxy never
 * changes a real texture, and a display list runs it at once instead of keeping it.
 * Run on Mesa's OSMesa and on fixedfunc's library, the printed lines must be the same and
 * the images match.
 *
 * usage: proxy_tex [out.ppm] */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 16
#define H 16

/* The proxy's level `level` as glGetTexLevelParameteriv answers it, and the error. */
static void level(const char *what, GLenum proxy, GLint lvl) {
  GLint w = -1, h = -1, d = -1, b = -1, f = -1, r = -1, g = -1, a = -1;
  glGetTexLevelParameteriv(proxy, lvl, GL_TEXTURE_DEPTH, &d);
  glGetTexLevelParameteriv(proxy, lvl, GL_TEXTURE_BORDER, &b);
  glGetTexLevelParameteriv(proxy, lvl, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(proxy, lvl, GL_TEXTURE_HEIGHT, &h);
  glGetTexLevelParameteriv(proxy, lvl, GL_TEXTURE_INTERNAL_FORMAT, &f);
  glGetTexLevelParameteriv(proxy, lvl, GL_TEXTURE_RED_SIZE, &r);
  glGetTexLevelParameteriv(proxy, lvl, GL_TEXTURE_GREEN_SIZE, &g);
  glGetTexLevelParameteriv(proxy, lvl, GL_TEXTURE_ALPHA_SIZE, &a);
  GLfloat fw = -1;
  glGetTexLevelParameterfv(proxy, lvl, GL_TEXTURE_WIDTH, &fw);
  printf("%-32s %dx%dx%d b%d 0x%x r%d g%d a%d (%.0f) err 0x%x\n", what, w, h, d, b, f, r, g,
         a, fw, glGetError());
}

/* The error flag after the call, then the level: one call's two records. */
static void checked(const char *what, GLenum proxy, GLint lvl) {
  err(what);
  level(what, proxy, lvl);
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "proxy_tex.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  level("2D before any proxy", GL_PROXY_TEXTURE_2D, 0);

  glTexImage1D(GL_PROXY_TEXTURE_1D, 0, GL_RGBA, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  checked("1D 64 RGBA", GL_PROXY_TEXTURE_1D, 0);
  glTexImage1D(GL_PROXY_TEXTURE_1D, 2, GL_LUMINANCE8, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("1D level 2 LUMINANCE8");
  level("1D level 2", GL_PROXY_TEXTURE_1D, 2);
  level("1D level 0 kept", GL_PROXY_TEXTURE_1D, 0);
  glTexImage1D(GL_PROXY_TEXTURE_1D, 0, GL_RGBA, 100000, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  checked("1D 100000", GL_PROXY_TEXTURE_1D, 0);
  level("1D level 2 after", GL_PROXY_TEXTURE_1D, 2);

  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGB5, 64, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  checked("2D 64x32 RGB5", GL_PROXY_TEXTURE_2D, 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, 3, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  level("2D 16x16 3", GL_PROXY_TEXTURE_2D, 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 1, GL_RGBA4, 8192, 8192, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  checked("2D level 1 8192x8192", GL_PROXY_TEXTURE_2D, 1);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 1, GL_RGBA, 8193, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  checked("2D level 1 8193x4", GL_PROXY_TEXTURE_2D, 1);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 100000, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  checked("2D 100000x4", GL_PROXY_TEXTURE_2D, 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_ALPHA8, 30, 6, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  level("2D 30x6 ALPHA8", GL_PROXY_TEXTURE_2D, 0);

  /* The errors of a real image. */
  glTexImage2D(GL_PROXY_TEXTURE_2D, -1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("2D level -1");
  glTexImage2D(GL_PROXY_TEXTURE_2D, 15, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("2D level 15");
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, -4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("2D width -4");
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("2D border 2");
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, 0x1234, NULL);
  err("2D bad type");
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               NULL);
  err("2D depth format, colour data");
  level("2D after the errors", GL_PROXY_TEXTURE_2D, 0);

  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  checked("cube 64x64", GL_PROXY_TEXTURE_CUBE_MAP, 0);
  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 64, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  checked("cube 64x32", GL_PROXY_TEXTURE_CUBE_MAP, 0);
  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 20000, 20000, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               NULL);
  checked("cube 20000x20000", GL_PROXY_TEXTURE_CUBE_MAP, 0);
  level("cube face", GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0);

  /* A border of 1: the sizes include it, each at least 2 and at most 2 + the largest. */
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 66, 34, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  checked("2D 66x34 border 1", GL_PROXY_TEXTURE_2D, 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 2, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  level("2D 2x2 border 1", GL_PROXY_TEXTURE_2D, 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 1, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  checked("2D 1x4 border 1", GL_PROXY_TEXTURE_2D, 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 1, GL_RGBA, 8194, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  level("2D level 1 8194x4 border 1", GL_PROXY_TEXTURE_2D, 1);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 1, GL_RGBA, 8195, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  level("2D level 1 8195x4 border 1", GL_PROXY_TEXTURE_2D, 1);
  glTexImage1D(GL_PROXY_TEXTURE_1D, 0, GL_RGB8, 6, 1, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  level("1D 6 border 1", GL_PROXY_TEXTURE_1D, 0);
  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  level("cube 6x6 border 1", GL_PROXY_TEXTURE_CUBE_MAP, 0);
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 6, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  checked("3D 6x6x6 border 1", GL_PROXY_TEXTURE_3D, 0);
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 6, 6, 6, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("3D border 2");

  /* A proxy in a display list runs at once; the list keeps nothing of it. */
  glNewList(1, GL_COMPILE);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA8, 32, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glEndList();
  checked("2D proxy compiled", GL_PROXY_TEXTURE_2D, 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glCallList(1);
  level("2D after the list is called", GL_PROXY_TEXTURE_2D, 0);

  /* No real texture changes: the bound 2D texture keeps its 4x4 image and texels. */
  replace_texture_panels();
  GLubyte s[4 * 4 * 4];
  for (unsigned i = 0; i < sizeof s; i++) s[i] = (GLubyte)(i * 13);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, s);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  glTexImage1D(GL_PROXY_TEXTURE_1D, 0, GL_RGB, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  level("real 2D after proxies", GL_TEXTURE_2D, 0);
  level("real 1D after proxies", GL_TEXTURE_1D, 0);
  glGetTexParameteriv(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &(GLint){0});
  err("glGetTexParameteriv of a proxy");
  glTexParameteri(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  err("glTexParameteri of a proxy");
  glTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, s);
  err("glTexSubImage2D of a proxy");
  glBindTexture(GL_PROXY_TEXTURE_2D, 1);
  err("glBindTexture of a proxy");
  glEnable(GL_TEXTURE_2D);
  textured_square();
  err("drawn");
  return finish(out, ctx, buf, W, H);
}
