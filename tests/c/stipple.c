/* Stippled lines as the programs of the era drew them: GL_LINES, GL_LINE_STRIP and
 * GL_LINE_LOOP under several patterns and repeat factors, wide and smooth-coloured lines,
 * lines from vertex arrays and from a display list, and a strip crossing itself; then the
 * stipple's glGet answers (the factor clamped to [1, 256]), its attribute groups and its
 * errors, one line each. Run on Mesa's OSMesa and on fixedfunc's library, the printed
 * lines must be the same and the images equal.
 *
 * usage: stipple [out.ppm] */
#include <GL/osmesa.h>
#include <stdio.h>
#include "report.h"

#define W 96
#define H 96

static void enabled(const char *what) {
  printf("%-40s %d  err 0x%x\n", what, glIsEnabled(GL_LINE_STIPPLE), glGetError());
}

/* How many pixels of row y from x0 to x1 are lit, and the bits of the first 16. */
static void row(const char *what, int x0, int x1, int y) {
  GLubyte p[4 * W];
  glReadPixels(x0, y, x1 - x0, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  int lit = 0;
  unsigned bits = 0;
  for (int i = 0; i < x1 - x0; i++) {
    int on = p[4 * i] > 0 || p[4 * i + 1] > 0 || p[4 * i + 2] > 0;
    lit += on;
    if (i < 16 && on) bits |= 1u << i;
  }
  printf("%-40s %d lit, first 16: 0x%04x  err 0x%x\n", what, lit, bits, glGetError());
}

int main(int argc, char **argv) {
  static GLubyte buffer[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) return 1;
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);

  /* The answers: GL defaults, then the values set, the factor clamped. */
  enabled("LINE_STIPPLE default");
  ints("LINE_STIPPLE_PATTERN default", GL_LINE_STIPPLE_PATTERN);
  ints("LINE_STIPPLE_REPEAT default", GL_LINE_STIPPLE_REPEAT);
  glLineStipple(0, 0x1234);
  ints("REPEAT after factor 0", GL_LINE_STIPPLE_REPEAT);
  glLineStipple(1000, 0xABCD);
  ints("REPEAT after factor 1000", GL_LINE_STIPPLE_REPEAT);
  ints("PATTERN 0xABCD", GL_LINE_STIPPLE_PATTERN);
  glPushAttrib(GL_LINE_BIT);
  glLineStipple(3, 0x00FF);
  glEnable(GL_LINE_STIPPLE);
  enabled("enabled inside LINE_BIT");
  glPopAttrib();
  enabled("LINE_BIT popped");
  ints("PATTERN popped", GL_LINE_STIPPLE_PATTERN);
  glPushAttrib(GL_ENABLE_BIT);
  glEnable(GL_LINE_STIPPLE);
  glPopAttrib();
  enabled("ENABLE_BIT popped");
  glBegin(GL_LINES);
  glLineStipple(2, 0x0F0F);
  glEnd();
  err("glLineStipple inside glBegin");
  ints("PATTERN unchanged", GL_LINE_STIPPLE_PATTERN);

  /* Row 2: one x-major line from a pixel centre; rows 6 and 10: two segments as GL_LINES
   * (the count restarts) and as a strip (it runs on). */
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x0F3D);
  glColor3f(1, 1, 1);
  glBegin(GL_LINES);
  glVertex2f(0.5f, 2.5f); glVertex2f(90.5f, 2.5f);
  glVertex2f(0.5f, 6.5f); glVertex2f(40.5f, 6.5f);
  glVertex2f(40.5f, 6.5f); glVertex2f(90.5f, 6.5f);
  glEnd();
  glBegin(GL_LINE_STRIP);
  glVertex2f(0.5f, 10.5f); glVertex2f(40.5f, 10.5f); glVertex2f(90.5f, 10.5f);
  glEnd();
  row("one line", 0, 90, 2);
  row("two segments", 40, 90, 6);
  row("a strip", 40, 90, 10);

  /* A loop crossing itself with a colour per vertex, factor 1, pattern 0xAAAA. */
  glLineStipple(1, 0xAAAA);
  glBegin(GL_LINE_LOOP);
  glColor3f(1, 0, 0); glVertex2f(5, 15);
  glColor3f(0, 1, 0); glVertex2f(90, 45.5f);
  glColor3f(0, 0, 1); glVertex2f(90, 15);
  glColor3f(1, 1, 0); glVertex2f(5.25f, 44.75f);
  glEnd();
  row("loop, bottom edge", 5, 90, 15);

  /* Wide lines, factor 256 (one bit covers the window) and 0x0001. */
  glLineWidth(3);
  glLineStipple(256, 0x0001);
  glColor3f(0, 1, 1);
  glBegin(GL_LINES);
  glVertex2f(4, 52); glVertex2f(92, 56);
  glEnd();
  glLineStipple(4, 0x0001);
  glBegin(GL_LINES);
  glVertex2f(4, 60); glVertex2f(92, 60);
  glEnd();
  glLineWidth(1);
  row("factor 4, 0x0001, wide", 0, 92, 60);

  /* Vertex arrays, elements and a display list. */
  static const GLfloat v[] = {3, 66, 90, 70.5f, 50.5f, 92, 8, 80, 70.25f, 88.75f};
  static const GLuint order[] = {4, 1, 3, 0};
  glLineStipple(3, 0x6B5D);
  glColor3f(1, 0.5f, 0);
  glVertexPointer(2, GL_FLOAT, 0, v);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_LINE_STRIP, 0, 5);
  glTranslatef(2, -1, 0);
  glDrawElements(GL_LINE_LOOP, 4, GL_UNSIGNED_INT, order);
  glDisableClientState(GL_VERTEX_ARRAY);
  glNewList(1, GL_COMPILE);
  glBegin(GL_LINE_STRIP);
  glVertex2f(5, 30); glVertex2f(45, 38); glVertex2f(88, 20);
  glEnd();
  glEndList();
  glColor3f(0.5f, 0.5f, 1);
  glCallList(1);
  err("drawing");
  glFinish();
  if (argc > 1 && !write_ppm(argv[1], buffer, W, H)) return 3;
  OSMesaDestroyContext(ctx);
  return 0;
}
