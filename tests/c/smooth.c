/* Antialiased points and lines (POINT_SMOOTH, LINE_SMOOTH) as programs of the era drew
 * them: blended over a background, translucent, through the alpha and depth tests, in
 * polygon POINT and LINE modes, from a display list, of every size and width from below one pixel to
 * thirteen, at fractional positions. Each 32x32 panel of the 128x128 image is one case. Run
 * on Mesa's OSMesa and on fixedfunc's library, the printed lines must be the same and the
 * images match.
 *
 * usage: smooth [out.ppm] */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"

#define W 128
#define H 128

/* Panel (col, row) of the 4x4 grid: its viewport, with x and y in 0..32. */
static void panel(int col, int row) {
  glViewport(col * 32, row * 32, 32, 32);
  glScissor(col * 32, row * 32, 32, 32);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/* Ten points of sizes growing along a row, at fractional positions. */
static void point_row(float y, float size0, float step) {
  for (int i = 0; i < 4; i++) {
    glPointSize(size0 + step * (float)i);
    glBegin(GL_POINTS);
    glVertex2f(3.3f + 8.1f * (float)i, y + 0.37f * (float)i);
    glEnd();
  }
}

static void lines_fan(float width) {
  glLineWidth(width);
  glBegin(GL_LINES);
  glColor4f(1, 1, 1, 1);
  glVertex2f(1.3f, 2.2f);
  glVertex2f(30.6f, 9.7f);
  glColor4f(1, 0.8f, 0.2f, 1);
  glVertex2f(2.1f, 28.4f);
  glVertex2f(29.2f, 17.1f);
  glColor4f(0.2f, 0.9f, 1, 1);
  glVertex2f(16.5f, 1.0f);
  glVertex2f(13.2f, 31.0f);
  glEnd();
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "smooth.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  GLubyte *buffer = calloc(W * H, 4);
  if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) {
    fprintf(stderr, "no context\n");
    return 1;
  }
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, 32, 0, 32, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_SCISSOR_TEST);
  glClearColor(0.15f, 0.15f, 0.2f, 1);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

  GLfloat range[2] = {-1, -1};
  glGetFloatv(GL_SMOOTH_POINT_SIZE_RANGE, range);
  printf("%-40s %g %g  err 0x%x\n", "SMOOTH_POINT_SIZE_RANGE", range[0], range[1], glGetError());
  glGetFloatv(GL_SMOOTH_LINE_WIDTH_RANGE, range);
  printf("%-40s %g %g  err 0x%x\n", "SMOOTH_LINE_WIDTH_RANGE", range[0], range[1], glGetError());
  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_LINE_SMOOTH);
  printf("%-40s %d %d  err 0x%x\n", "glIsEnabled POINT_SMOOTH, LINE_SMOOTH",
         glIsEnabled(GL_POINT_SMOOTH), glIsEnabled(GL_LINE_SMOOTH), glGetError());
  glHint(GL_POINT_SMOOTH_HINT, GL_NICEST);
  glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
  ints("POINT_SMOOTH_HINT", GL_POINT_SMOOTH_HINT);
  ints("LINE_SMOOTH_HINT", GL_LINE_SMOOTH_HINT);

  /* Row 0: opaque points, blended; the sizes 0.25 … 13. */
  glEnable(GL_BLEND);
  panel(0, 0);
  glColor4f(1, 1, 1, 1);
  point_row(4.2f, 0.25f, 0.5f);
  point_row(12.6f, 2.0f, 0.5f);
  point_row(22.1f, 3.5f, 1.5f);
  /* Translucent points: the factor exceeds 1 inside the inner circle. */
  panel(1, 0);
  glColor4f(1, 0.6f, 0.2f, 0.4f);
  point_row(4.2f, 1.0f, 1.0f);
  glColor4f(0.2f, 1, 0.4f, 0.7f);
  point_row(13.6f, 5.0f, 1.0f);
  glColor4f(0.4f, 0.5f, 1, 0.25f);
  glPointSize(13.0f);
  glBegin(GL_POINTS);
  glVertex2f(16.4f, 25.2f);
  glEnd();
  /* The alpha test sees the scaled alpha: alpha 0.45 passes GREATER 0.5 only inside. */
  panel(2, 0);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glColor4f(1, 1, 0.3f, 0.45f);
  point_row(8.2f, 6.0f, 2.0f);
  glAlphaFunc(GL_LESS, 0.5f);
  glColor4f(0.3f, 1, 1, 0.45f);
  point_row(22.2f, 6.0f, 2.0f);
  glDisable(GL_ALPHA_TEST);
  /* No blending: the disc is written whole. */
  panel(3, 0);
  glDisable(GL_BLEND);
  glColor4f(0.9f, 0.3f, 0.6f, 0.5f);
  point_row(6.3f, 1.5f, 1.25f);
  point_row(20.7f, 7.0f, 1.0f);
  glEnable(GL_BLEND);

  /* Row 1: points through the depth test, smooth-shaded polygons in POINT mode. */
  panel(0, 1);
  glEnable(GL_DEPTH_TEST);
  glColor4f(0.3f, 0.3f, 0.6f, 1);
  glRectf(8, 0, 24, 32); /* at depth 0 */
  glColor4f(1, 1, 1, 1);
  glPointSize(7.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 4; i++) glVertex3f(4.5f + 7.6f * (float)i, 16.3f, i % 2 ? 0.5f : -0.5f);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  panel(1, 1);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glPointSize(5.0f);
  glBegin(GL_TRIANGLES);
  glColor4f(1, 0, 0, 1);
  glVertex2f(4.2f, 4.4f);
  glColor4f(0, 1, 0, 1);
  glVertex2f(27.7f, 6.1f);
  glColor4f(0, 0, 1, 1);
  glVertex2f(15.3f, 27.6f);
  glEnd();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  /* Lines of width 1, and 2.5. */
  panel(2, 1);
  lines_fan(1.0f);
  panel(3, 1);
  lines_fan(2.5f);

  /* Row 2: wide lines, translucent lines, strips and loops. */
  panel(0, 2);
  lines_fan(4.0f);
  panel(1, 2);
  glColor4f(0.9f, 0.9f, 0.3f, 0.5f);
  glLineWidth(3.0f);
  glBegin(GL_LINE_STRIP);
  glVertex2f(2.5f, 3.5f);
  glVertex2f(29.5f, 8.25f);
  glVertex2f(4.75f, 17.5f);
  glVertex2f(28.1f, 29.3f);
  glEnd();
  panel(2, 2);
  glLineWidth(1.5f);
  glBegin(GL_LINE_LOOP);
  glColor4f(1, 0.2f, 0.2f, 1);
  glVertex2f(3.3f, 3.1f);
  glColor4f(0.2f, 1, 0.2f, 1);
  glVertex2f(28.6f, 5.7f);
  glColor4f(0.2f, 0.2f, 1, 1);
  glVertex2f(25.1f, 28.8f);
  glColor4f(1, 1, 1, 1);
  glVertex2f(5.2f, 24.4f);
  glEnd();
  /* Polygons in LINE mode: their edges are smooth lines. */
  panel(3, 2);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glLineWidth(2.0f);
  glColor4f(0.6f, 1, 0.8f, 1);
  glBegin(GL_QUADS);
  glVertex2f(4.4f, 5.6f);
  glVertex2f(27.3f, 3.2f);
  glVertex2f(25.9f, 26.1f);
  glVertex2f(6.2f, 28.7f);
  glEnd();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);

  /* Row 3: smooth lines and points from a display list; without blending; off again. */
  panel(0, 3);
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  lines_fan(2.0f);
  glColor4f(1, 1, 1, 0.8f);
  point_row(24.4f, 3.0f, 1.0f);
  glEndList();
  glCallList(list);
  panel(1, 3);
  glDisable(GL_BLEND);
  lines_fan(3.0f);
  glEnable(GL_BLEND);
  glTranslatef(3.7f, 0, 0);
  lines_fan(1.5f);
  glLoadIdentity();
  panel(2, 3);
  glDisable(GL_POINT_SMOOTH);
  glDisable(GL_LINE_SMOOTH);
  glColor4f(1, 1, 1, 1);
  point_row(8.2f, 1.0f, 2.0f);
  lines_fan(2.0f);
  /* Smooth again after glPushAttrib/glPopAttrib of the point and line bits. */
  panel(3, 3);
  glPushAttrib(GL_POINT_BIT | GL_LINE_BIT);
  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_LINE_SMOOTH);
  glPopAttrib();
  printf("%-40s %d %d  err 0x%x\n", "after glPopAttrib", glIsEnabled(GL_POINT_SMOOTH),
         glIsEnabled(GL_LINE_SMOOTH), glGetError());
  glEnable(GL_POINT_SMOOTH);
  glColor4f(1, 0.5f, 1, 0.9f);
  point_row(16.4f, 4.0f, 2.5f);

  glFinish();
  err("end");
  if (!write_ppm(out, buffer, W, H)) return 1;
  OSMesaDestroyContext(ctx);
  free(buffer);
  return 0;
}
