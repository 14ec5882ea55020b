/* Textures given a border of 1 texel: Mesa's state tracker strips it at the call
 * (StripTextureBorder), so glTexImage1D/2D/3D and glCopyTexImage1D/2D make a level two
 * texels narrower on each bordered side, with border 0, holding the image's interior — a
 * height or depth of 2 is kept whole — and a proxy keeps its border. Printed: each call's
 * error, the level's width, height and border, the texels read back, and a 6x6 image with
 * border 1 drawn NEAREST over the window (its 4x4 interior, one texel per 8x8 block).
 *
 * usage: texture_border [out.ppm] */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"
#define W 32
#define H 32

static void level(GLenum target, const char *what) {
  GLint w = -7, h = -7, b = -7;
  glGetTexLevelParameteriv(target, 0, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(target, 0, GL_TEXTURE_HEIGHT, &h);
  glGetTexLevelParameteriv(target, 0, GL_TEXTURE_BORDER, &b);
  printf("%-40s w %d h %d border %d  err 0x%x\n", what, w, h, b, glGetError());
}

/* The first `n` texels of TEXTURE_2D's level 0 as RGB hex; the byte after them. */
static void texels(const char *what, int n) {
  GLubyte back[65 * 4];
  memset(back, 0xee, sizeof back);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  printf("%-40s", what);
  for (int i = 0; i < n; i++) printf(" %02x%02x%02x", back[4 * i], back[4 * i + 1], back[4 * i + 2]);
  printf(" | %02x  err 0x%x\n", back[4 * n], glGetError());
}

/* glTexImage2D of `img` as w x h with `border`, and its error; for n >= 0 the level, and
 * for n > 0 its first n texels. */
static void image_2d(const GLubyte *img, int w, int h, int border, int n) {
  char what[64];
  snprintf(what, sizeof what, "TexImage2D %dx%d border %d", w, h, border);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, border, GL_RGBA, GL_UNSIGNED_BYTE, img);
  err(what);
  if (n < 0) return;
  level(GL_TEXTURE_2D, "  level");
  if (n > 0) texels("  texels", n);
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "texture_border.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 3;
  /* A 6x6 image (or 27 texels of a 3x3x3 one): texel i = (7i, 255 - 7i, 40 (i mod 6)). */
  GLubyte img[6 * 6 * 4];
  for (int i = 0; i < 36; i++) {
    img[4 * i] = (GLubyte)(i * 7);
    img[4 * i + 1] = (GLubyte)(255 - i * 7);
    img[4 * i + 2] = (GLubyte)(i % 6 * 40);
    img[4 * i + 3] = 255;
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);

  image_2d(img, 6, 6, 1, 16);
  image_2d(img, 5, 6, 1, 12);
  image_2d(img, 4, 2, 1, 4); /* a height of 2 is kept whole */
  image_2d(img, 2, 2, 1, 0);
  image_2d(img, 1, 1, 1, -1);
  image_2d(img, 6, 1, 1, -1);
  image_2d(img, 6, 6, 2, -1);
  image_2d(img, 6, 6, -1, -1);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  err("proxy 6x6 border 1");
  level(GL_PROXY_TEXTURE_2D, "  proxy level");
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 6);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
  err("TexImage2D 4x4 border 1, ROW_LENGTH 6");
  level(GL_TEXTURE_2D, "  level");
  texels("  texels", 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glTexSubImage2D(GL_TEXTURE_2D, 0, -1, -1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
  err("TexSubImage2D at (-1, -1)");
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
  err("TexImage1D 6 border 1");
  level(GL_TEXTURE_1D, "  level");
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 3, 3, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
  err("TexImage3D 3x3x3 border 1");
  level(GL_TEXTURE_3D, "  level");

  glClearColor(0.2f, 0.4f, 0.6f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 6, 6, 1);
  err("CopyTexImage2D 6x6 border 1");
  level(GL_TEXTURE_2D, "  level");
  texels("  texels", 16);
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 0, 0, 6, 1);
  err("CopyTexImage1D 6 border 1");
  level(GL_TEXTURE_1D, "  level");

  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  textured_square();
  err("draw");
  return finish(out, ctx, buf, W, H);
}
