/* Wide points and lines in a viewport smaller than the buffer: GL 1.5 §3.3 clips a point
 * by its centre only and §3.4 a wide line as a line, so what lies beyond the viewport is
 * drawn up to the buffer's edge, as Mesa's OSMesa draws it. Square and smooth points on
 * the viewport's edge and corner, a wide line leaving the viewport, a point whose centre
 * is outside (not drawn); the centres sit a little inside the right and top planes
 * (one exactly on them is drawn a pixel left or down of Mesa's here); then a viewport
 * beyond MAX_VIEWPORT_DIMS, clamped. Each prints its lit pixel count and bounding box. (A point
 * under distance attenuation is cut at the viewport here: core GL takes a per-vertex size
 * only with PROGRAM_POINT_SIZE, under which llvmpipe clips it as a square.)
 *
 * usage: wide_viewport [out.ppm] */
#include <GL/osmesa.h>
#include <stdio.h>
#include "report.h"

#define W 64
#define H 64

static void lit(const char *what) {
  GLubyte p[4 * W * H];
  glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, p);
  int n = 0, x0 = W, y0 = H, x1 = -1, y1 = -1;
  for (int y = 0; y < H; y++)
    for (int x = 0; x < W; x++)
      if (p[4 * (y * W + x)]) {
        n++;
        x0 = x < x0 ? x : x0;
        y0 = y < y0 ? y : y0;
        x1 = x > x1 ? x : x1;
        y1 = y > y1 ? y : y1;
      }
  printf("%-28s %4d lit  [%d,%d]-[%d,%d]  err 0x%x\n", what, n, x0, y0, x1, y1, glGetError());
  glClear(GL_COLOR_BUFFER_BIT);
}

static void point(GLfloat x, GLfloat y) {
  glBegin(GL_POINTS);
  glVertex2f(x, y);
  glEnd();
}

int main(int argc, char **argv) {
  GLubyte *buf = calloc(W * H, 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!buf || !ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glViewport(20, 20, 20, 20);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);

  glPointSize(7);
  point(0.97f, 0.97f);
  lit("size 7 on the corner");
  point(-1, 0);
  lit("size 7 on the left edge");
  point(1.2f, 0);
  lit("size 7, centre outside");
  glEnable(GL_POINT_SMOOTH);
  point(1, -1);
  lit("smooth size 7 on a corner");
  glDisable(GL_POINT_SMOOTH);
  glPointSize(4);
  point(0, 0.97f);
  lit("size 4 on the top edge");

  glLineWidth(7);
  glBegin(GL_LINES);
  glVertex2f(-1, -0.5f);
  glVertex2f(-1, 0.5f);
  glEnd();
  lit("width 7 along the left edge");
  glBegin(GL_LINES);
  glVertex2f(0, 0);
  glVertex2f(3, 0.4f);
  glEnd();
  lit("width 7 leaving the viewport");

  /* A side beyond MAX_VIEWPORT_DIMS is clamped to it (GL 1.5 §2.11.1). */
  GLint v[4];
  glViewport(-5, -6, 100000, 70000);
  glGetIntegerv(GL_VIEWPORT, v);
  printf("%-28s %d %d %d %d  err 0x%x\n", "viewport 100000 x 70000", v[0], v[1], v[2], v[3],
         glGetError());
  return finish(argc > 1 ? argv[1] : "wide_viewport.ppm", ctx, buf, W, H);
}
