/* Edge flags on triangle strips, triangle fans and quad strips, which Mesa honours: its
 * draw module cuts a strip into triangles (i, i+1, i+2) for even i and (i+1, i, i+2) for
 * odd, a fan into (0, i+1, i+2), and draws each triangle's edge from corner k to the next
 * only where corner k's vertex has its flag set, a quad strip's quad edge by edge as a
 * quad's; GL 1.5 §2.6.2 would draw every edge of strips and fans. Panels: each type in
 * LINE mode with one flag cleared in turn, through glBegin/glEnd, an edge-flag array with
 * glDrawArrays and glDrawElements; POINT mode blended (a vertex is drawn once for every
 * triangle that has it); the current flag FALSE with no array; separate front and back
 * modes; a stippled outline; flat colours. Each panel prints its lit pixels. Run on Mesa's
 * OSMesa and on fixedfunc's library, the printed lines must be the same and the images the
 * same pixel for pixel.
 *
 * usage: edge_strips [out.ppm] */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"

#define W 256
#define H 256
#define N 6

static GLubyte *image;

static const GLfloat STRIP[N][2] = {{2, 2}, {4, 28}, {12, 8}, {15, 30}, {26, 3}, {29, 27}};
static const GLfloat FAN[N][2] = {{16, 2}, {30, 9}, {28, 24}, {17, 30}, {4, 23}, {2, 8}};
static const GLfloat COLORS[N][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                     {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};

/* Pixels of the 32×32 panel at (x, y) that are not black. */
static int lit(int x, int y) {
  glFinish();
  int n = 0;
  for (int j = y; j < y + 32; j++)
    for (int i = x; i < x + 32; i++) {
      const GLubyte *p = image + 4 * (j * W + i);
      if (p[0] || p[1] || p[2]) n++;
    }
  return n;
}

static void panel(int col, int row) {
  glViewport(32 * col, 32 * row, 32, 32);
  glScissor(32 * col, 32 * row, 32, 32);
}

/* The primitive of panel column `col`, row `row`: vertices of `at`, flag `cleared` FALSE. */
static void immediate(GLenum mode, const GLfloat (*at)[2], int cleared) {
  glBegin(mode);
  for (int k = 0; k < N; k++) {
    glEdgeFlag(k == cleared ? GL_FALSE : GL_TRUE);
    glColor3fv(COLORS[k]);
    glVertex2fv(at[k]);
  }
  glEnd();
  glEdgeFlag(GL_TRUE);
}

static void arrays(GLenum mode, const GLfloat (*at)[2], int cleared, int indexed) {
  GLboolean flags[N];
  for (int k = 0; k < N; k++) flags[k] = k != cleared;
  static const GLubyte order[N] = {0, 1, 2, 3, 4, 5};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, at);
  glColorPointer(3, GL_FLOAT, 0, COLORS);
  glEdgeFlagPointer(0, flags);
  if (indexed)
    glDrawElements(mode, N, GL_UNSIGNED_BYTE, order);
  else
    glDrawArrays(mode, 0, N);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_EDGE_FLAG_ARRAY);
}

static const GLenum MODES[3] = {GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUAD_STRIP};
static const char *const NAMES[3] = {"strip", "fan", "quad strip"};

static const GLfloat (*shape(int m))[2] { return m == 1 ? FAN : STRIP; }

int main(int argc, char **argv) {
  OSMesaContext ctx;
  image = open_window(&ctx, W, H);
  if (!image) return 3;
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 32, 0, 32, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_SCISSOR_TEST);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  /* Rows 0–2: each type, the flag of vertex 0..5 cleared in columns 0..5; columns 6 and
   * 7 through arrays (flag 2 cleared) drawn and indexed. */
  for (int m = 0; m < 3; m++) {
    for (int k = 0; k < N; k++) {
      panel(k, m);
      immediate(MODES[m], shape(m), k);
      printf("%-10s flag %d cleared      lit %d\n", NAMES[m], k, lit(32 * k, 32 * m));
    }
    panel(6, m);
    arrays(MODES[m], shape(m), 2, 0);
    printf("%-10s array drawn         lit %d\n", NAMES[m], lit(192, 32 * m));
    panel(7, m);
    arrays(MODES[m], shape(m), 3, 1);
    printf("%-10s array indexed       lit %d\n", NAMES[m], lit(224, 32 * m));
  }
  /* Row 3: POINT mode, blended additively (a vertex drawn twice is brighter), flag 1
   * cleared; then the current flag FALSE with no array, in LINE mode. */
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glPointSize(3);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  for (int m = 0; m < 3; m++) {
    panel(m, 3);
    glColor3f(0.25f, 0.25f, 0.25f);
    glBegin(MODES[m]);
    for (int k = 0; k < N; k++) {
      glEdgeFlag(k == 1 ? GL_FALSE : GL_TRUE);
      glVertex2fv(shape(m)[k]);
    }
    glEnd();
    glEdgeFlag(GL_TRUE);
    printf("%-10s points blended      lit %d\n", NAMES[m], lit(32 * m, 96));
  }
  glDisable(GL_BLEND);
  glPointSize(1);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  for (int m = 0; m < 3; m++) {
    panel(3 + m, 3);
    glEdgeFlag(GL_FALSE);
    glBegin(MODES[m]);
    for (int k = 0; k < N; k++) glVertex2fv(shape(m)[k]);
    glEnd();
    glEdgeFlag(GL_TRUE);
    printf("%-10s current flag FALSE  lit %d\n", NAMES[m], lit(96 + 32 * m, 96));
  }
  /* Row 4: front faces LINE, back faces FILL (the strip's triangles alternate no facing;
   * the glFrontFace flip makes them back faces), flag 4 cleared; row 5: a stippled outline
   * with flag 3 cleared; row 6: flat shading, flag 0 cleared. */
  for (int m = 0; m < 3; m++) {
    panel(m, 4);
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    glPointSize(2);
    immediate(MODES[m], shape(m), 4);
    glFrontFace(GL_CW);
    panel(3 + m, 4);
    immediate(MODES[m], shape(m), 4);
    glFrontFace(GL_CCW);
    glPointSize(1);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    printf("%-10s front LINE back POINT lit %d %d\n", NAMES[m], lit(32 * m, 128),
           lit(96 + 32 * m, 128));
    panel(m, 5);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(1, 0x3333);
    immediate(MODES[m], shape(m), 3);
    glDisable(GL_LINE_STIPPLE);
    printf("%-10s stippled            lit %d\n", NAMES[m], lit(32 * m, 160));
    panel(m, 6);
    glShadeModel(GL_FLAT);
    immediate(MODES[m], shape(m), 0);
    glShadeModel(GL_SMOOTH);
    printf("%-10s flat                lit %d\n", NAMES[m], lit(32 * m, 192));
  }
  printf("errors                        err 0x%x\n", glGetError());
  return finish(argc > 1 ? argv[1] : "edge_strips.ppm", ctx, image, W, H);
}
