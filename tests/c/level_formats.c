/* Mipmap levels whose internal formats are stored alike but named differently: GL 1.5
 * §3.8.10 makes a mipmapped texture complete only when every level has the base level's
 * internal format, and Mesa compares the formats as the program named them — RGBA and
 * RGBA8, RGB and RGB8, 4 and RGBA are different formats, and the texture is incomplete
 * (its unit off: the fragment colour shows). The same names on every level are complete,
 * and a NEAREST filter needs the base level only. Each panel prints the format each level
 * reports. Run on Mesa's OSMesa and on fixedfunc's library, the printed lines must be the
 * same and the images match.
 *
 * usage: level_formats [out.ppm] */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 96
#define H 8
static GLubyte *buf;
static int panels;

static void panel(GLint level0, GLint level1, GLenum filter) {
  int x = panels * 8;
  glBindTexture(GL_TEXTURE_2D, 1 + panels);
  panels++;
  const GLubyte red[16] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, level0, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, red);
  glTexImage2D(GL_TEXTURE_2D, 1, level1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, red);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  GLint named[2];
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &named[0]);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_INTERNAL_FORMAT, &named[1]);
  glViewport(x, 0, 8, 8);
  textured_square();
  glFinish();
  const GLubyte *p = buf + 4 * (4 * W + x + 4);
  printf("levels 0x%04x 0x%04x filter 0x%x  %3d %3d %3d %3d err 0x%x\n", named[0], named[1],
         filter, p[0], p[1], p[2], p[3], glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "level_formats.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor4f(0.2f, 0.4f, 0.6f, 0.8f);
  const GLenum mip = GL_NEAREST_MIPMAP_NEAREST;
  panel(GL_RGBA, GL_RGBA8, mip);
  panel(GL_RGBA8, GL_RGBA, mip);
  panel(4, GL_RGBA, mip);
  panel(GL_RGB, GL_RGB8, mip);
  panel(GL_LUMINANCE, GL_LUMINANCE8, mip);
  panel(GL_ALPHA, GL_ALPHA8, mip);
  panel(3, GL_RGB, mip);
  panel(GL_RGBA, GL_RGBA, mip);
  panel(GL_RGBA8, GL_RGBA8, mip);
  panel(4, 4, mip);
  panel(GL_RGBA, GL_RGBA8, GL_NEAREST);
  panel(GL_LUMINANCE8, GL_LUMINANCE8, mip);
  return finish(out, ctx, buf, W, H);
}
