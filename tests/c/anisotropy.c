/* EXT_texture_filter_anisotropic as programs of the early 2000s used it: the extension
 * named in the extension string, MAX_TEXTURE_MAX_ANISOTROPY_EXT queried and given to
 * TEXTURE_MAX_ANISOTROPY_EXT. The parameter's rules (below 1 an error, a NaN taken, above
 * the maximum clamped, the integer query rounded, every target, glPushAttrib(TEXTURE_BIT),
 * inside glBegin/glEnd), then a mipmapped checkerboard floor seen at a grazing angle,
 * sampled trilinearly with anisotropy 1, 4 and 16 side by side: the checks stay sharp
 * further into the distance as it grows.
 * Run on Mesa's OSMesa and on fixedfunc's library, the printed lines must be the same and
 * the images match.
 *
 * usage: anisotropy [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 96
#define H 64
#define T 64

static void parameter(const char *what, GLfloat value) {
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, value);
  GLenum e = glGetError();
  GLfloat f = -7;
  GLint i = -7;
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &i);
  printf("%-24s err 0x%x float %g int %d\n", what, e, f, i);
}

/* A floor one unit below the eye from near to far, each unit of it one repeat of the
 * texture (two checks), in a panel a third of the buffer wide. */
static void floor_panel(int panel, GLfloat anisotropy) {
  glViewport(panel * (W / 3), 0, W / 3, H);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, anisotropy);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex3f(-3, -1, -1);
  glTexCoord2f(6, 0);
  glVertex3f(3, -1, -1);
  glTexCoord2f(6, 39);
  glVertex3f(3, -1, -40);
  glTexCoord2f(0, 39);
  glVertex3f(-3, -1, -40);
  glEnd();
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "anisotropy.ppm";
  OSMesaContext ctx;
  GLubyte *buf = open_window(&ctx, W, H);
  if (!buf) return 1;
  printf("extension named %d\n", extension_named("GL_EXT_texture_filter_anisotropic"));
  GLfloat max = -7;
  GLint max_i = -7;
  glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &max);
  glGetIntegerv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &max_i);
  printf("maximum %g %d err 0x%x\n", max, max_i, glGetError());

  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  GLfloat f = -7;
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
  printf("default %g err 0x%x\n", f, glGetError());
  parameter("0.5", 0.5f);
  parameter("1", 1);
  parameter("4", 4);
  parameter("16", 16);
  parameter("17", 17);
  parameter("0", 0);
  parameter("-1", -1);
  parameter("1.5", 1.5f);
  parameter("2.7", 2.7f);
  parameter("1000", 1000);
  parameter("NaN", strtof("nan", NULL));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 3);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
  printf("glTexParameteri 3: %g err 0x%x\n", f, glGetError());
  GLfloat fv[4] = {5, 0, 0, 0};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, fv);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
  printf("glTexParameterfv 5: %g err 0x%x\n", f, glGetError());
  GLint iv[4] = {0, 0, 0, 0};
  glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, iv);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
  printf("glTexParameteriv 0: %g err 0x%x\n", f, glGetError());
  glPushAttrib(GL_TEXTURE_BIT);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 2);
  glPopAttrib();
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
  printf("after glPopAttrib %g err 0x%x\n", f, glGetError());
  GLenum targets[3] = {GL_TEXTURE_1D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP};
  for (int k = 0; k < 3; k++) {
    glTexParameterf(targets[k], GL_TEXTURE_MAX_ANISOTROPY_EXT, 8);
    GLenum e = glGetError();
    glGetTexParameterfv(targets[k], GL_TEXTURE_MAX_ANISOTROPY_EXT, &f);
    printf("target 0x%x: %g err 0x%x\n", targets[k], f, e);
  }
  glBegin(GL_TRIANGLES);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 4);
  glEnd();
  printf("inside glBegin/glEnd err 0x%x\n", glGetError());
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_MAX_ANISOTROPY_EXT, 4);
  printf("glTexEnv with it err 0x%x\n", glGetError());

  /* A checkerboard of 32×32-texel squares, white and blue, with its mipmaps. */
  static GLubyte texels[T * T * 3];
  for (int y = 0; y < T; y++)
    for (int x = 0; x < T; x++) {
      GLubyte *p = texels + 3 * (y * T + x);
      int on = ((x / 32) + (y / 32)) % 2;
      p[0] = on ? 250 : 20;
      p[1] = on ? 250 : 60;
      p[2] = on ? 250 : 200;
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, T, T, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1, 50);
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  GLfloat levels[3] = {1, 4, 16};
  for (int k = 0; k < 3; k++) floor_panel(k, levels[k]);
  glFinish();
  printf("draw err 0x%x\n", glGetError());
  return finish(out, ctx, buf, W, H);
}
