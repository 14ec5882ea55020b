/* Texture internal formats as programs of the era name them: GL 1.0's component counts
 * (glTexImage2D(…, 3, …), the Red Book's habit), GL 1.1's sized formats (RGB5, RGBA4,
 * LUMINANCE4, ALPHA12, INTENSITY16…) and GL 1.4's MIRRORED_REPEAT wrap, each drawn into a
 * panel and its texel printed, with the internal format the level answers (the name as
 * the program gave it). Run on Mesa's OSMesa and on fixedfunc's library, the
 * printed lines must be the same and the images match.
 *
 * The texels are multiples of 17 (exact in 4 bits), so a format Mesa keeps in 4 bits gives
 * the same values as the layer's 8-bit storage; RGB5 and RGB5_A1, which Mesa keeps in 5
 * bits and the layer in 8, are left out (221 reads 222 on Mesa).
 *
 * usage: formats [out.ppm] */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 64
#define H 32
static GLubyte *buf;
static int panels;

static void draw(const char *what) {
  glViewport((panels % 8) * 8, (panels / 8) * 8, 8, 8);
  panels++;
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glTexCoord2f(-1, -1); glVertex2f(-1, -1);
  glTexCoord2f(2, -1); glVertex2f(1, -1);
  glTexCoord2f(2, 2); glVertex2f(1, 1);
  glTexCoord2f(-1, 2); glVertex2f(-1, 1);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glFinish();
  const GLubyte *p = buf + 4 * ((((panels - 1) / 8) * 8 + 4) * W + ((panels - 1) % 8) * 8 + 4);
  printf("%-28s %d %d %d %d err %x\n", what, p[0], p[1], p[2], p[3], glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "formats.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  GLubyte t[16] = {255, 136, 51, 170, 0, 68, 204, 255, 17, 238, 119, 85, 221, 34, 153, 0};
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  struct { GLint format; const char *name; } formats[] = {
      {1, "component count 1"}, {2, "component count 2"}, {3, "component count 3"},
      {4, "component count 4"}, {GL_RGBA4, "RGBA4"},
      {GL_LUMINANCE4, "LUMINANCE4"}, {GL_ALPHA12, "ALPHA12"},
      {GL_INTENSITY16, "INTENSITY16"}, {GL_LUMINANCE4_ALPHA4, "LUMINANCE4_ALPHA4"},
      {GL_RGB10_A2, "RGB10_A2"}, {GL_RGBA16, "RGBA16"}, {GL_RGB4, "RGB4"},
  };
  for (unsigned i = 0; i < sizeof formats / sizeof formats[0]; i++) {
    glTexImage2D(GL_TEXTURE_2D, 0, formats[i].format, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
    draw(formats[i].name);
    GLint named = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &named);
    printf("%-28s internal format 0x%x err %x\n", formats[i].name, named, glGetError());
  }
  glTexImage2D(GL_TEXTURE_2D, 0, 5, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  err("component count 5");
  glTexImage2D(GL_TEXTURE_2D, 0, 0, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  err("component count 0");
  glTexImage2D(GL_TEXTURE_2D, 0, 3, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
  err("mirrored repeat");
  {
    GLint w = 0;
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &w);
    printf("wrap s 0x%x err %x\n", (unsigned)w, glGetError());
  }
  draw("mirrored repeat");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  draw("mirrored repeat linear");
  glCopyTexImage2D(GL_TEXTURE_2D, 0, 4, 0, 0, 2, 2, 0);
  err("copy with component count 4");
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 2, 2, 0);
  {
    GLint named = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPONENTS, &named);
    printf("copy as GL_RGB internal format 0x%x err %x\n", named, glGetError());
  }
  glViewport(0, 0, W, H);
  return finish(out, ctx, buf, W, H);
}
