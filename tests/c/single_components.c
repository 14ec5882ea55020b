/* Texture images of one colour component: glTexImage2D with GL_RED, GL_GREEN and GL_BLUE
 * data in UNSIGNED_BYTE, FLOAT, SHORT and UNSIGNED_SHORT, into RGBA and LUMINANCE_ALPHA,
 * and a glTexSubImage2D of RED into an RGBA image (GL 1.5 §3.6.4: a group becomes RGBA,
 * the missing colour components 0 and alpha 1, before it is stored). Eight 32×64 panels
 * drawn with REPLACE and blending, the errors after each call (a depth texture refuses
 * RED data), and the RGBA read back of a GREEN image.
 *
 * usage: single_components OUT.ppm */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include "report.h"

#define W 256
#define H 64

static void panel(int i) { glViewport(i * 32, 0, 32, 64); }

int main(int argc, char **argv) {
  OSMesaContext ctx;
  GLubyte *buf = open_window(&ctx, W, H);
  if (!buf) return 3;
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0.3f, 0.3f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  replace_texture();
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

  GLubyte ub[16];
  GLfloat fl[16];
  GLshort sh[16];
  GLushort us[16];
  for (int i = 0; i < 16; i++) {
    ub[i] = (GLubyte)(i * 16 + 8);
    fl[i] = i / 15.0f;
    sh[i] = (GLshort)(i * 2000 - 9000);
    us[i] = (GLushort)(i * 4000);
  }
  static const GLenum formats[] = {GL_RED, GL_GREEN, GL_BLUE};
  for (int f = 0; f < 3; f++) {
    panel(f);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, formats[f], GL_UNSIGNED_BYTE, ub);
    err("teximage ub");
    textured_square();
  }
  panel(3);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RED, GL_FLOAT, fl);
  err("teximage float");
  textured_square();
  panel(4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_GREEN, GL_SHORT, sh);
  err("teximage short");
  textured_square();
  /* BLUE into LUMINANCE_ALPHA: luminance from red (0), alpha 1. */
  panel(5);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 4, 4, 0, GL_BLUE, GL_UNSIGNED_SHORT, us);
  err("teximage la");
  textured_square();
  /* RED over the middle of an RGBA image: green and blue become 0 there, alpha 1. */
  panel(6);
  GLubyte rgba[64];
  for (int i = 0; i < 64; i++) rgba[i] = (GLubyte)(255 - i * 3);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_RED, GL_UNSIGNED_BYTE, ub);
  err("subimage");
  textured_square();
  panel(7);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 4, 0, GL_RED, GL_UNSIGNED_BYTE, ub);
  err("depth red");
  GLubyte back[64];
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_GREEN, GL_UNSIGNED_BYTE, ub);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  printf("back");
  for (int i = 0; i < 16; i++) printf(" %d", back[i]);
  printf("\n");
  return finish(argc > 1 ? argv[1] : "out.ppm", ctx, buf, W, H);
}
