/* EXT_abgr: GL_ABGR_EXT images, alpha first, drawn, read, and uploaded and read back as
 * textures in unsigned bytes, the packed types that take four components, and floats;
 * 5_6_5 (three components) is INVALID_OPERATION. One line per call: the error and what
 * was read. The image: the drawn rectangles.
 *
 * usage: abgr OUT.ppm */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>
#include <string.h>

#include "report.h"

#define W 32
#define H 16

static void bytes(const char *what, const GLubyte *b, int n) {
  printf("%-40s err 0x%x:", what, glGetError());
  for (int i = 0; i < n; i++) printf(" %d", b[i]);
  printf("\n");
}

int main(int argc, char **argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s OUT.ppm\n", argv[0]);
    return 2;
  }
  OSMesaContext ctx;
  GLubyte *buf = open_window(&ctx, W, H);
  if (!buf) return 1;
  printf("%-40s %d\n", "GL_EXT_abgr listed", extension_named("GL_EXT_abgr"));
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  GLubyte img[4 * 4 * 4];
  for (int i = 0; i < 16; i++) {
    img[4 * i] = (GLubyte)(10 + i);
    img[4 * i + 1] = (GLubyte)(100 + i);
    img[4 * i + 2] = (GLubyte)(150 + i);
    img[4 * i + 3] = (GLubyte)(200 + i);
  }
  static const GLfloat floats[16] = {0.1f, 0.2f, 0.3f,  0.4f, 0.5f, 0.6f,  0.7f, 0.8f,
                                     0.9f, 1,    0,     0.25f, 0.5f, 0.75f, 1,    0};
  glRasterPos2i(1, 1);
  glDrawPixels(4, 4, GL_ABGR_EXT, GL_UNSIGNED_BYTE, img);
  err("glDrawPixels UNSIGNED_BYTE");
  glRasterPos2i(6, 1);
  glDrawPixels(4, 4, GL_ABGR_EXT, GL_UNSIGNED_INT_8_8_8_8, img);
  err("glDrawPixels UNSIGNED_INT_8_8_8_8");
  glRasterPos2i(11, 1);
  glDrawPixels(2, 2, GL_ABGR_EXT, GL_UNSIGNED_SHORT_4_4_4_4, img);
  err("glDrawPixels UNSIGNED_SHORT_4_4_4_4");
  glRasterPos2i(16, 1);
  glDrawPixels(2, 2, GL_ABGR_EXT, GL_UNSIGNED_SHORT_5_6_5, img);
  err("glDrawPixels UNSIGNED_SHORT_5_6_5");
  glDrawPixels(2, 2, GL_ABGR_EXT, GL_FLOAT, floats);
  err("glDrawPixels FLOAT");

  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_ABGR_EXT, GL_UNSIGNED_BYTE, img);
  err("glTexImage2D");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_ABGR_EXT, GL_UNSIGNED_BYTE, img + 8);
  err("glTexSubImage2D");
  GLubyte back[64];
  memset(back, 0, sizeof back);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_ABGR_EXT, GL_UNSIGNED_BYTE, back);
  bytes("glGetTexImage ABGR texel 0", back, 4);
  bytes("glGetTexImage ABGR texel (1, 1)", back + 20, 4);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  bytes("glGetTexImage RGBA texel 0", back, 4);

  glReadPixels(1, 1, 1, 1, GL_ABGR_EXT, GL_UNSIGNED_BYTE, back);
  bytes("glReadPixels UNSIGNED_BYTE", back, 4);
  glReadPixels(6, 1, 1, 1, GL_ABGR_EXT, GL_UNSIGNED_INT_8_8_8_8_REV, back);
  bytes("glReadPixels UNSIGNED_INT_8_8_8_8_REV", back, 4);
  glReadPixels(11, 1, 1, 1, GL_ABGR_EXT, GL_UNSIGNED_SHORT_4_4_4_4, back);
  bytes("glReadPixels UNSIGNED_SHORT_4_4_4_4", back, 2);
  GLfloat f[4] = {-1, -1, -1, -1};
  glReadPixels(16, 1, 1, 1, GL_ABGR_EXT, GL_FLOAT, f);
  printf("%-40s err 0x%x: %.4f %.4f %.4f %.4f\n", "glReadPixels FLOAT", glGetError(), f[0], f[1],
         f[2], f[3]);
  return finish(argv[1], ctx, buf, W, H);
}
