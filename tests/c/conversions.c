/* The conversions a program's integers go through, compared bit for bit with Mesa's:
 * glColor of every integer type (the current colour printed as exact hexadecimal floats
 * and as GL_CURRENT_COLOR integers), colour arrays of the signed types drawn as points
 * (the pixel read back: a zero byte stays zero), and glLineWidth/glPointSize of NaN
 * (not <= 0, so kept) and of 0 (INVALID_VALUE).
 *
 * usage: conversions [out.ppm] */
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include "report.h"

#define W 16
#define H 16

static void current(const char *what) {
  GLfloat f[4];
  GLint i[4];
  glGetFloatv(GL_CURRENT_COLOR, f);
  glGetIntegerv(GL_CURRENT_COLOR, i);
  printf("%-24s %a %a %a %a  %d %d %d %d  err 0x%x\n", what, f[0], f[1], f[2], f[3], i[0],
         i[1], i[2], i[3], glGetError());
}

static void point_of(const char *what, GLenum type, const void *rgba) {
  static const GLfloat origin[2] = {8, 8};
  GLubyte p[4];
  glClear(GL_COLOR_BUFFER_BIT);
  glVertexPointer(2, GL_FLOAT, 0, origin);
  glColorPointer(4, type, 0, rgba);
  glDrawArrays(GL_POINTS, 0, 1);
  glReadPixels(8, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  printf("%-24s %3d %3d %3d %3d  err 0x%x\n", what, p[0], p[1], p[2], p[3], glGetError());
}

static void size(const char *what, GLenum pname) {
  GLfloat f = -1;
  glGetFloatv(pname, &f);
  printf("%-24s %s  err 0x%x\n", what, isnan(f) ? "nan" : f == 1.0f ? "1" : "other",
         glGetError());
}

int main(int argc, char **argv) {
  GLubyte *buf = calloc(W * H, 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!buf || !ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);

  glColor4b(-1, 1, 64, -64);
  current("glColor4b");
  glColor4b(-128, 127, 0, 3);
  current("glColor4b extremes");
  glColor4s(-1, 16384, 0, -16384);
  current("glColor4s");
  glColor4us(0, 257, 65534, 32767);
  current("glColor4us");
  glColor4ub(0, 127, 254, 3);
  current("glColor4ub");
  glColor4i(-1, 1, 1073741824, 0);
  current("glColor4i");
  glColor4ui(0, 0x7FFFFFFFu, 0xFFFFFFFEu, 0x01010101u);
  current("glColor4ui");

  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  static const GLbyte bytes[4] = {127, -1, 64, 0};
  static const GLshort shorts[4] = {32767, -1, 16384, 0};
  static const GLint ints[4] = {2147483647, -1, 1073741824, 0};
  point_of("GL_BYTE array", GL_BYTE, bytes);
  point_of("GL_SHORT array", GL_SHORT, shorts);
  point_of("GL_INT array", GL_INT, ints);
  glDisableClientState(GL_COLOR_ARRAY);

  glLineWidth(NAN);
  size("glLineWidth(NaN)", GL_LINE_WIDTH);
  glPointSize(NAN);
  size("glPointSize(NaN)", GL_POINT_SIZE);
  glLineWidth(0);
  size("glLineWidth(0)", GL_LINE_WIDTH);
  glPointSize(-1);
  size("glPointSize(-1)", GL_POINT_SIZE);
  return finish(argc > 1 ? argv[1] : "conversions.ppm", ctx, buf, W, H);
}
