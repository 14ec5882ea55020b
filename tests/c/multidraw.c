/* glMultiDrawArrays and glMultiDrawElements (GL 1.4) as programs drew strips and fans of
 * a mesh in one call: from client arrays, from index lists in client memory and in an
 * element-array buffer object (offsets), and compiled into a display list; then the
 * errors of bad calls, one line each. Run on Mesa's OSMesa and on fixedfunc's library,
 * the printed lines must be the same and the images match.
 *
 * usage: multidraw [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>
#include "report.h"

#define W 96
#define H 64

static void pixel(const char *what, int x, int y) {
  GLubyte p[4] = {0};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  printf("%-40s %d %d %d %d  err 0x%x\n", what, p[0], p[1], p[2], p[3], glGetError());
}

/* A 4×4 grid of vertices over one 32×32 panel (its lower-left corner at the origin),
 * coloured by position. */
static GLfloat grid[16][2];
static GLubyte colours[16][4];

static void make_grid(void) {
  for (int j = 0; j < 4; j++)
    for (int i = 0; i < 4; i++) {
      grid[4 * j + i][0] = 2.0f + 9.0f * i;
      grid[4 * j + i][1] = 2.0f + 9.0f * j;
      colours[4 * j + i][0] = (GLubyte)(60 * i + 40);
      colours[4 * j + i][1] = (GLubyte)(60 * j + 40);
      colours[4 * j + i][2] = (GLubyte)(200 - 40 * i);
      colours[4 * j + i][3] = 255;
    }
}

int main(int argc, char **argv) {
  static GLubyte buffer[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) return 1;
  make_grid();
  glViewport(0, 0, W, H);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glVertexPointer(2, GL_FLOAT, 0, grid);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, colours);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);

  /* GL 1.5 §2.8: each list is drawn as glDrawArrays would draw it. Mesa 22.3 draws
   * nothing at all when the first list's count is 0, and the layer follows it (a Mesa
   * deviation); the window is cleared after. */
  {
    GLint f[2] = {0, 3};
    GLsizei n[2] = {0, 3};
    static GLubyte px[W * H * 4];
    glMultiDrawArrays(GL_TRIANGLES, f, n, 2);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    int drawn = 0;
    for (int k = 0; k < W * H; k++) drawn += px[4 * k + 2] != 26;
    printf("%-40s %d  err 0x%x\n", "first list empty: pixels drawn", drawn, glGetError());
    glClear(GL_COLOR_BUFFER_BIT);
  }

  /* Row strips as separate lists of indices: the grid's rows 0–1 and 2–3. */
  static const GLushort strip0[8] = {0, 4, 1, 5, 2, 6, 3, 7};
  static const GLushort strip1[8] = {8, 12, 9, 13, 10, 14, 11, 15};
  static const GLushort strip2[8] = {4, 8, 5, 9, 6, 10, 7, 11};
  const void *strips[3] = {strip0, strip1, strip2};
  GLsizei eight[3] = {8, 8, 8};

  /* Panel 1 (lower left): glMultiDrawArrays of the three strips laid out one after the
   * other, the last one cut short. */
  static GLfloat laid[24][2];
  static GLubyte laid_colours[24][4];
  for (int k = 0; k < 24; k++) {
    const GLushort *s = strips[k / 8];
    laid[k][0] = grid[s[k % 8]][0];
    laid[k][1] = grid[s[k % 8]][1];
    for (int c = 0; c < 4; c++) laid_colours[k][c] = colours[s[k % 8]][c];
  }
  glVertexPointer(2, GL_FLOAT, 0, laid);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, laid_colours);
  GLint first[3] = {0, 8, 16};
  GLsizei count[3] = {8, 8, 6};
  glMultiDrawArrays(GL_TRIANGLE_STRIP, first, count, 3);
  err("multi draw arrays");
  glVertexPointer(2, GL_FLOAT, 0, grid);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, colours);

  /* Panel 2 (lower middle): glMultiDrawElements of two strips from client memory. */
  glPushMatrix();
  glTranslatef(32, 0, 0);
  glMultiDrawElements(GL_TRIANGLE_STRIP, eight, GL_UNSIGNED_SHORT, strips, 2);
  err("multi draw elements");
  glPopMatrix();

  /* Panel 3 (lower right): the three strips' indices in an element-array buffer,
   * given as offsets. */
  GLuint buf = 0;
  glGenBuffers(1, &buf);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buf);
  GLushort all[24];
  for (int k = 0; k < 8; k++) {
    all[k] = strip0[k];
    all[8 + k] = strip2[k];
    all[16 + k] = strip1[k];
  }
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof all, all, GL_STATIC_DRAW);
  const void *offsets[3] = {(const void *)0, (const void *)16, (const void *)32};
  glPushMatrix();
  glTranslatef(64, 0, 0);
  glMultiDrawElements(GL_TRIANGLE_STRIP, eight, GL_UNSIGNED_SHORT, offsets, 3);
  err("multi draw elements from a buffer");
  glPopMatrix();
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);

  /* Panel 4 (upper left): lines and points through glMultiDrawArrays, at pixel centres
   * (a 3-pixel point on a pixel corner would cover pixels by ties). */
  glPushMatrix();
  glTranslatef(0.5f, 32.5f, 0);
  GLint lfirst[2] = {0, 12};
  GLsizei lcount[2] = {4, 4};
  glMultiDrawArrays(GL_LINE_STRIP, lfirst, lcount, 2);
  glPointSize(3);
  glMultiDrawArrays(GL_POINTS, first, count, 3);
  glPointSize(1);
  err("lines and points");
  glPopMatrix();

  /* Panel 5 (upper middle): a display list compiles the arrays as they are now; the
   * arrays change before it runs. */
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMultiDrawElements(GL_TRIANGLE_STRIP, eight, GL_UNSIGNED_SHORT, strips, 3);
  glEndList();
  err("compiled");
  static GLubyte grey[16][4];
  for (int k = 0; k < 16; k++) grey[k][0] = grey[k][1] = grey[k][2] = grey[k][3] = 128;
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, grey);
  glPushMatrix();
  glTranslatef(32, 32, 0);
  glCallList(list);
  err("list called");
  glPopMatrix();
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, colours);

  /* Panel 6 (upper right): an incomplete triangle and a count of 0 draw nothing; the
   * third list draws the triangle of vertices 3, 4 and 5. */
  glPushMatrix();
  glTranslatef(64, 32, 0);
  GLint zfirst[3] = {0, 0, 3};
  GLsizei zcount[3] = {2, 0, 3};
  glMultiDrawArrays(GL_TRIANGLES, zfirst, zcount, 3);
  glMultiDrawArrays(GL_TRIANGLES, first, count, 0);
  err("empty lists");
  glPopMatrix();

  pixel("panel 1 (8,8)", 8, 8);
  pixel("panel 2 (40,20)", 40, 20);
  pixel("panel 3 (80,20)", 80, 20);
  pixel("panel 5 (40,52)", 40, 52);
  pixel("panel 6 (80,45)", 80, 45);
  pixel("panel 6 (80,39)", 80, 39);

  /* Errors, in Mesa's order: the draw count first, then the mode (and type), then the
   * counts. */
  GLsizei neg[3] = {3, -1, 3};
  glMultiDrawArrays(GL_TRIANGLES, first, count, -1);
  err("arrays drawcount -1");
  glMultiDrawArrays(GL_TRIANGLES, first, neg, 3);
  err("arrays count -1");
  glMultiDrawArrays(GL_TEXTURE_2D, first, count, 3);
  err("arrays bad mode");
  glMultiDrawArrays(GL_TEXTURE_2D, first, count, -1);
  err("arrays bad mode, drawcount -1");
  glMultiDrawArrays(GL_TEXTURE_2D, first, neg, 3);
  err("arrays bad mode, count -1");
  glMultiDrawArrays(GL_TEXTURE_2D, first, count, 0);
  err("arrays bad mode, drawcount 0");
  glMultiDrawElements(GL_TRIANGLES, eight, GL_UNSIGNED_SHORT, strips, -1);
  err("elements drawcount -1");
  glMultiDrawElements(GL_TRIANGLES, neg, GL_UNSIGNED_SHORT, strips, 3);
  err("elements count -1");
  glMultiDrawElements(GL_TRIANGLES, eight, GL_FLOAT, strips, 3);
  err("elements type FLOAT");
  glMultiDrawElements(GL_TEXTURE_2D, eight, GL_UNSIGNED_SHORT, strips, 3);
  err("elements bad mode");
  glMultiDrawElements(GL_TRIANGLES, neg, GL_FLOAT, strips, 3);
  err("elements count -1, type FLOAT");
  glMultiDrawElements(GL_TEXTURE_2D, neg, GL_UNSIGNED_SHORT, strips, 3);
  err("elements bad mode, count -1");
  glMultiDrawElements(GL_TRIANGLES, eight, GL_FLOAT, strips, -1);
  err("elements type FLOAT, drawcount -1");
  glMultiDrawElements(GL_TRIANGLES, eight, GL_FLOAT, strips, 0);
  err("elements type FLOAT, drawcount 0");
  glBegin(GL_TRIANGLES);
  glMultiDrawArrays(GL_TRIANGLES, first, count, 3);
  glEnd();
  err("inside begin/end");
  glNewList(list, GL_COMPILE);
  glMultiDrawArrays(GL_TRIANGLES, first, neg, 3);
  glEndList();
  err("compiled with count -1");
  glCallList(list);
  err("... raised when the list runs");

  glFinish();
  glDeleteLists(list, 1);
  glDeleteBuffers(1, &buf);
  err("deleted");
  if (argc > 1 && !write_ppm(argv[1], buffer, W, H)) return 3;
  OSMesaDestroyContext(ctx);
  return 0;
}
