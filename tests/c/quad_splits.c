/* Which diagonal a GL_QUADS quad is split along, as Mesa's OSMesa shows it: a square whose
 * one corner alone is white (smooth shading shows the diagonal) drawn by glBegin/glEnd, by
 * glDrawArrays, from a display list compiled from each, and with GL_COMPILE_AND_EXECUTE;
 * then a bow-tie quad (non-convex: the two splits cover different pixels) under flat
 * shading, by glBegin/glEnd and glDrawArrays. Each panel prints the grey level at two
 * points on either side of the v0-v2 diagonal and its lit pixel count.
 *
 * usage: quad_splits [out.ppm] */
#include <GL/osmesa.h>
#include <stdio.h>
#include "report.h"

#define W 192
#define H 96
#define P 48 /* panel size */

static const GLfloat square[] = {4, 4, 44, 4, 44, 44, 4, 44};
static const GLfloat corner_white[] = {0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0};
static const GLfloat bowtie[] = {4, 4, 44, 44, 44, 4, 4, 44};
static const GLfloat bowtie_colours[] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0};

static void immediate(const GLfloat *xy, const GLfloat *rgb) {
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; i++) {
    glColor3fv(rgb + 3 * i);
    glVertex2fv(xy + 2 * i);
  }
  glEnd();
}

static void arrays(const GLfloat *xy, const GLfloat *rgb) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, xy);
  glColorPointer(3, GL_FLOAT, 0, rgb);
  glDrawArrays(GL_QUADS, 0, 4);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
}

/* Panel k (0..7): four in each of two rows. */
static void at(int k) {
  glLoadIdentity();
  glTranslatef((float)(P * (k % 4)), (float)(P * (k / 4)), 0);
}

static void report(const char *what, int k) {
  GLubyte below[4], above[4], all[4 * P * P];
  int x = P * (k % 4), y = P * (k / 4);
  glReadPixels(x + 30, y + 20, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, below);
  glReadPixels(x + 20, y + 30, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, above);
  glReadPixels(x, y, P, P, GL_RGBA, GL_UNSIGNED_BYTE, all);
  int lit = 0;
  for (int i = 0; i < P * P; i++) lit += all[4 * i] || all[4 * i + 1] || all[4 * i + 2];
  printf("%-28s below %3d %3d %3d  above %3d %3d %3d  lit %4d  err 0x%x\n", what, below[0],
         below[1], below[2], above[0], above[1], above[2], lit, glGetError());
}

int main(int argc, char **argv) {
  GLubyte *buf = calloc(W * H, 4);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!buf || !ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);

  GLuint lists = glGenLists(3);
  glNewList(lists, GL_COMPILE);
  immediate(square, corner_white);
  glEndList();
  glNewList(lists + 1, GL_COMPILE);
  arrays(square, corner_white);
  glEndList();

  at(0);
  immediate(square, corner_white);
  report("smooth, glBegin/glEnd", 0);
  at(1);
  arrays(square, corner_white);
  report("smooth, glDrawArrays", 1);
  at(2);
  glCallList(lists);
  report("smooth, list of glBegin", 2);
  at(3);
  glCallList(lists + 1);
  report("smooth, list of glDrawArrays", 3);
  at(4);
  glNewList(lists + 2, GL_COMPILE_AND_EXECUTE);
  immediate(square, corner_white);
  glEndList();
  report("smooth, compile and execute", 4);
  at(5);
  glCallList(lists + 2);
  report("smooth, that list called", 5);

  glShadeModel(GL_FLAT);
  at(6);
  immediate(bowtie, bowtie_colours);
  report("flat bow-tie, glBegin/glEnd", 6);
  at(7);
  arrays(bowtie, bowtie_colours);
  report("flat bow-tie, glDrawArrays", 7);
  return finish(argc > 1 ? argv[1] : "quad_splits.ppm", ctx, buf, W, H);
}
