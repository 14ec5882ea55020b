/* The texture object's own TEXTURE_LOD_BIAS (GL 1.4, Table 6.16) and TEXTURE_PRIORITY
 * (GL 1.1) through each glTexParameter form, read back with glGetTexParameter (PRIORITY
 * clamped to [0, 1], as an integer the colour-style conversion: 1 reads INT_MAX), and
 * glPrioritizeTextures, which sets the priorities of named objects. The object's bias is
 * added to the unit's: with a bias of 1 a 16x16 panel of a 16x16 texture samples level 1,
 * and a unit bias of -1 brings it back to level 0. Run on Mesa's OSMesa and on fixedfunc's
 * library, the printed lines must be the same and the images match.
 *
 * usage: tex_params [out.ppm] */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 64
#define H 16
static GLubyte *buf;
static int panels;

static void params(const char *what) {
  GLfloat f[2] = {-9, -9};
  GLint i[2] = {-9, -9};
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, &f[0]);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &f[1]);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, &i[0]);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &i[1]);
  printf("%-34s bias %g %d priority %g %d err 0x%x\n", what, f[0], i[0], f[1], i[1],
         glGetError());
}

static void panel(const char *what) {
  int x = panels * 16;
  panels++;
  glViewport(x, 0, 16, 16);
  textured_square();
  glFinish();
  const GLubyte *p = buf + 4 * (8 * W + x + 8);
  printf("%-34s %3d %3d %3d %3d err 0x%x\n", what, p[0], p[1], p[2], p[3], glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "tex_params.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  GLuint tex[2];
  glGenTextures(2, tex);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  params("defaults");
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.25f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 0.25f);
  params("glTexParameterf 1.25 0.25");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, -2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 3);
  params("glTexParameteri -2 3");
  const GLfloat fv[2] = {0.5f, -0.5f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, &fv[0]);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &fv[1]);
  params("glTexParameterfv 0.5 -0.5");
  const GLint iv[2] = {3, 0};
  glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, &iv[0]);
  glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &iv[1]);
  params("glTexParameteriv 3 0");
  const GLclampf priorities[3] = {0.75f, 2.0f, 0.5f};
  const GLuint names[3] = {tex[0], tex[1], 0};
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glPrioritizeTextures(3, names, priorities);
  err("glPrioritizeTextures");
  params("second texture");
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  params("first texture");
  glPrioritizeTextures(-1, names, priorities);
  err("glPrioritizeTextures(-1)");
  glPushAttrib(GL_TEXTURE_BIT);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 4);
  glPopAttrib();
  params("after a pushed and popped bias 4");

  GLubyte red[16 * 16 * 4], green[8 * 8 * 4];
  for (int i = 0; i < 16 * 16; i++) {
    red[4 * i] = 255; red[4 * i + 1] = 0; red[4 * i + 2] = 0; red[4 * i + 3] = 255;
  }
  for (int i = 0; i < 8 * 8; i++) {
    green[4 * i] = 0; green[4 * i + 1] = 255; green[4 * i + 2] = 0; green[4 * i + 3] = 255;
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, red);
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0);
  panel("object bias 0");
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1);
  panel("object bias 1");
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -1);
  panel("object bias 1, unit bias -1");
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 20);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -17);
  panel("object bias 20, unit bias -17");
  return finish(out, ctx, buf, W, H);
}
