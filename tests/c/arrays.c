/* Client vertex arrays, every draw call and several element types: six panels, each
 * drawn through another path — glDrawArrays, glDrawElements, glDrawRangeElements,
 * glInterleavedArrays, glArrayElement inside glBegin/glEnd, and an interleaved format
 * with a stride — into one image.
 *
 * usage: arrays OUT.ppm */
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

#include "gl_resolve.h"

#define W 192
#define H 128

static void panel(int i) {
  glViewport((i % 3) * 64, (i / 3) * 64, 64, 64);
}

int main(int argc, char **argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s OUT.ppm\n", argv[0]);
    return 2;
  }
  static GLubyte buffer[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) return 1;
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  /* 0: DrawArrays, float xyz, unsigned byte RGBA. */
  static const GLfloat tri[] = {-0.9f, -0.9f, 0, 0.9f, -0.9f, 0, 0, 0.9f, 0};
  static const GLubyte tri_rgba[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255};
  panel(0);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, tri);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, tri_rgba);
  glDrawArrays(GL_TRIANGLES, 0, 3);

  /* 1: DrawElements of quads, short xy scaled down, float RGB with a stride. */
  static const GLshort quad[] = {-1, -1, 1, -1, 1, 1, -1, 1};
  static const GLfloat quad_rgb[] = {1, 1, 0, 9, 0, 1, 1, 9, 1, 0, 1, 9, 1, 1, 1, 9};
  static const GLushort quad_idx[] = {0, 1, 2, 3};
  panel(1);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glScalef(0.8f, 0.8f, 1);
  glVertexPointer(2, GL_SHORT, 0, quad);
  glColorPointer(3, GL_FLOAT, 4 * sizeof(GLfloat), quad_rgb);
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_SHORT, quad_idx);
  glPopMatrix();

  /* 2: DrawRangeElements of a lit strip, double xyz, float normals, no colour array. */
  static const GLdouble strip[] = {-0.8, -0.8, 0, 0.8, -0.8, 0, -0.8, 0.8, 0, 0.8, 0.8, 0};
  static const GLfloat strip_n[] = {0, 0, 1, 0.7f, 0, 0.7f, -0.7f, 0, 0.7f, 0, 0.7f, 0.7f};
  static const GLuint strip_idx[] = {0, 1, 2, 3};
  panel(2);
  glDisableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glVertexPointer(3, GL_DOUBLE, 0, strip);
  glNormalPointer(GL_FLOAT, 0, strip_n);
  glDrawRangeElements(GL_TRIANGLE_STRIP, 0, 3, 4, GL_UNSIGNED_INT, strip_idx);
  glDisable(GL_LIGHTING);
  glDisableClientState(GL_NORMAL_ARRAY);

  /* 3: InterleavedArrays C4UB_V3F, packed. */
  static const struct {
    GLubyte c[4];
    GLfloat v[3];
  } fan[] = {{{255, 128, 0, 255}, {0, 0, 0}},      {{0, 128, 255, 255}, {0.9f, 0, 0}},
             {{128, 255, 0, 255}, {0, 0.9f, 0}},    {{255, 0, 128, 255}, {-0.9f, 0, 0}},
             {{0, 255, 128, 255}, {0, -0.9f, 0}},   {{0, 128, 255, 255}, {0.9f, 0, 0}}};
  panel(3);
  glInterleavedArrays(GL_C4UB_V3F, 0, fan);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 6);

  /* 4: ArrayElement inside glBegin/glEnd, with the fan's arrays. */
  panel(4);
  glBegin(GL_POLYGON);
  for (int i = 1; i < 5; i++) glArrayElement(i);
  glEnd();

  /* 5: T2F_C3F_V3F with an explicit stride of 9 floats (one unused). */
  static const GLfloat lines[] = {0, 0, 1, 0, 0, -0.9f, -0.9f, 0, 7, 1, 1, 0, 1, 0, 0.9f, 0.9f, 0, 7,
                                  0, 1, 0, 0, 1, -0.9f, 0.9f, 0, 7, 1, 0, 1, 1, 0, 0.9f, -0.9f, 0, 7};
  panel(5);
  glLineWidth(3);
  glInterleavedArrays(GL_T2F_C3F_V3F, 9 * sizeof(GLfloat), lines);
  glDrawArrays(GL_LINES, 0, 4);

  glFinish();
  GLenum err = glGetError();
  if (err != GL_NO_ERROR) {
    fprintf(stderr, "GL error 0x%x\n", err);
    return 1;
  }
  int ok = write_ppm(argv[1], buffer, W, H);
  OSMesaDestroyContext(ctx);
  return ok ? 0 : 1;
}
