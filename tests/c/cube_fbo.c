/* Render to a cube map as programs drew dynamic environment maps: each face of a cube map
 * texture attached to a framebuffer object with glFramebufferTexture2D(EXT) and the face's
 * own textarget (TEXTURE_CUBE_MAP_POSITIVE_X + i), cleared to its colour and drawn into,
 * its completeness and attachment queries answered; a face of a 2D texture, a 2D texture
 * named as a face, and a face through the 1D call refused; then the cube map sampled in the
 * window by direction (explicit (s, t, r) and NORMAL_MAP texgen) and read back face by
 * face. Run on Mesa's OSMesa and on fixedfunc's library, the printed lines must be the
 * same and the images the same pixel for pixel.
 *
 * usage: cube_fbo [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"

#define W 96
#define H 64
#define SIDE 16

static const GLfloat FACE_COLOURS[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                           {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};

int main(int argc, char **argv) {
  OSMesaContext ctx;
  GLubyte *image = open_window(&ctx, W, H);
  if (!image) return 3;
  GLuint cube, flat, fb;
  glGenTextures(1, &cube);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  for (int f = 0; f < 6; f++)
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA8, SIDE, SIDE, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, NULL);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glGenTextures(1, &flat);
  glBindTexture(GL_TEXTURE_2D, flat);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, SIDE, SIDE, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glGenFramebuffersEXT(1, &fb);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
  glViewport(0, 0, SIDE, SIDE);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, SIDE, 0, SIDE, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  for (int f = 0; f < 6; f++) {
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT,
                              GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, cube, 0);
    GLint face = -1, name = -1;
    glGetFramebufferAttachmentParameterivEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT,
                                             GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE_EXT,
                                             &face);
    glGetFramebufferAttachmentParameterivEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT,
                                             GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT, &name);
    GLenum status = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
    printf("face %d attached err 0x%x status 0x%x face 0x%x name %d\n", f, glGetError(), status,
           face, name == (GLint)cube);
    glClearColor(FACE_COLOURS[f][0] * 0.5f, FACE_COLOURS[f][1] * 0.5f, FACE_COLOURS[f][2] * 0.5f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3fv(FACE_COLOURS[f]);
    glBegin(GL_TRIANGLES);
    glVertex2f(2, 2);
    glVertex2f(14, 3 + f);
    glVertex2f(5, 14);
    glEnd();
    GLubyte px[4] = {0, 0, 0, 0};
    glReadPixels(6, 6, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    printf("face %d drawn          pixel %3d %3d %3d %3d err 0x%x\n", f, px[0], px[1], px[2],
           px[3], glGetError());
  }
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT,
                            GL_TEXTURE_CUBE_MAP_POSITIVE_Y, flat, 0);
  err("a 2D texture named as a face");
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, cube, 0);
  err("a cube map named as a 2D texture");
  glFramebufferTexture1DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT,
                            GL_TEXTURE_CUBE_MAP_POSITIVE_X, cube, 0);
  err("a face through the 1D call");
  glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT,
                            GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, cube, 1);
  printf("a level never given     err 0x%x status 0x%x\n", glGetError(),
         glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT));
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
  for (int f = 0; f < 6; f++) {
    GLubyte texels[SIDE * SIDE * 4];
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
    glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    const GLubyte *c = texels + 4 * (1 * SIDE + 1), *d = texels + 4 * (6 * SIDE + 6);
    printf("face %d read back       corner %3d %3d %3d inside %3d %3d %3d\n", f, c[0], c[1], c[2],
           d[0], d[1], d[2]);
  }
  /* The window: six panels sampling one face each by an explicit direction, then a
   * sphere-like fan through NORMAL_MAP texgen. */
  glViewport(0, 0, W, H);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_TEXTURE_CUBE_MAP);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  static const GLfloat AXES[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                     {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; f++) {
    float x = 16.0f * (float)f;
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) {
      float u = (k == 1 || k == 2) ? 0.9f : -0.9f, v = (k >= 2) ? 0.9f : -0.9f;
      const GLfloat *a = AXES[f];
      glTexCoord3f(a[0] + (a[0] == 0 ? u : 0), a[1] + (a[1] == 0 ? (a[0] != 0 ? u : v) : 0),
                   a[2] + (a[2] == 0 ? v : 0));
      glVertex2f(x + (k == 1 || k == 2 ? 16.0f : 0.0f), (k >= 2) ? 32.0f : 16.0f);
    }
    glEnd();
  }
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_GEN_R);
  glBegin(GL_TRIANGLE_FAN);
  glNormal3f(0, 0, 1);
  glVertex2f(48, 48);
  for (int k = 0; k <= 16; k++) {
    float a = (float)k * 6.2831853f / 16.0f;
    float cx = cosf(a), sy = sinf(a);
    glNormal3f(cx, sy, 0.2f);
    glVertex2f(48 + 14 * cx, 48 + 14 * sy);
  }
  glEnd();
  printf("errors                  err 0x%x\n", glGetError());
  return finish(argc > 1 ? argv[1] : "cube_fbo.ppm", ctx, image, W, H);
}
