/* Edge flags as the programs of the era used them: polygons drawn in GL_LINE and GL_POINT
 * mode with some edges hidden by glEdgeFlag inside glBegin/glEnd, by glEdgeFlagv, by the
 * current flag, by GL_EDGE_FLAG_ARRAY through glDrawArrays, glDrawElements and
 * glArrayElement, and from a display list; then the edge-flag answers (GL_EDGE_FLAG,
 * GL_EDGE_FLAG_ARRAY, its stride and pointer), the attribute stacks that hold them
 * (GL_CURRENT_BIT, GL_CLIENT_VERTEX_ARRAY_BIT), glInterleavedArrays disabling the array
 * and the errors, one line each. Run on Mesa's OSMesa and on fixedfunc's library, the
 * printed lines must be the same and the images equal.
 *
 * usage: edgeflags [out.ppm] */
#include <GL/osmesa.h>
#include <stdio.h>
#include "report.h"

#define W 128
#define H 96

static void flag(const char *what) {
  GLboolean b = 7;
  glGetBooleanv(GL_EDGE_FLAG, &b);
  printf("%-40s %d  err 0x%x\n", what, b, glGetError());
}

static void array_on(const char *what) {
  printf("%-40s %d  err 0x%x\n", what, glIsEnabled(GL_EDGE_FLAG_ARRAY), glGetError());
}

/* How many pixels of the rectangle are lit. */
static void lit(const char *what, int x0, int y0, int w, int h) {
  static GLubyte p[4 * W * H];
  glReadPixels(x0, y0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, p);
  int n = 0;
  for (int i = 0; i < w * h; i++) n += p[4 * i] > 0 || p[4 * i + 1] > 0 || p[4 * i + 2] > 0;
  printf("%-40s %d lit  err 0x%x\n", what, n, glGetError());
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

  /* The answers: GL defaults, the values set, the stacks. */
  flag("EDGE_FLAG default");
  array_on("EDGE_FLAG_ARRAY default");
  ints("EDGE_FLAG_ARRAY_STRIDE default", GL_EDGE_FLAG_ARRAY_STRIDE);
  glEdgeFlag(GL_FALSE);
  flag("after glEdgeFlag(FALSE)");
  glPushAttrib(GL_CURRENT_BIT);
  glEdgeFlag(GL_TRUE);
  flag("inside CURRENT_BIT");
  glPopAttrib();
  flag("CURRENT_BIT popped");
  static const GLboolean yes = 2;
  glEdgeFlagv(&yes);
  flag("glEdgeFlagv(2)");
  glBegin(GL_TRIANGLES);
  glEdgeFlag(GL_FALSE);
  glEnd();
  err("glEdgeFlag inside glBegin");
  flag("left by the pair");
  glEdgeFlag(GL_TRUE);

  static const GLboolean flags[] = {1, 0, 1, 1, 0, 1, 1, 0};
  static GLubyte padded[24];
  glEdgeFlagPointer(-1, flags);
  err("glEdgeFlagPointer stride -1");
  glEdgeFlagPointer(3, padded);
  ints("EDGE_FLAG_ARRAY_STRIDE 3", GL_EDGE_FLAG_ARRAY_STRIDE);
  GLvoid *ptr = NULL;
  glGetPointerv(GL_EDGE_FLAG_ARRAY_POINTER, &ptr);
  printf("%-40s %d  err 0x%x\n", "EDGE_FLAG_ARRAY_POINTER", ptr == (GLvoid *)padded,
         glGetError());
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glEdgeFlagPointer(0, flags);
  array_on("enabled inside CLIENT_VERTEX_ARRAY");
  glPopClientAttrib();
  array_on("CLIENT_VERTEX_ARRAY popped");
  ints("stride popped", GL_EDGE_FLAG_ARRAY_STRIDE);
  glGetPointerv(GL_EDGE_FLAG_ARRAY_POINTER, &ptr);
  printf("%-40s %d  err 0x%x\n", "pointer popped", ptr == (GLvoid *)padded, glGetError());
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  static const GLfloat v2f[] = {0, 0, 1, 0, 0, 1};
  glInterleavedArrays(GL_V2F, 0, v2f);
  array_on("after glInterleavedArrays");
  glDisableClientState(GL_VERTEX_ARRAY);

  /* Row 1: a quad, two triangles and a pentagon in LINE mode, flags inside the pairs. */
  glColor3f(1, 1, 1);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glBegin(GL_QUADS);
  glVertex2f(4.3f, 4.3f);
  glEdgeFlag(GL_FALSE);
  glVertex2f(36.3f, 6.3f);
  glEdgeFlag(GL_TRUE);
  glVertex2f(34.3f, 28.3f);
  glEdgeFlagv(&flags[1]);
  glVertex2f(6.3f, 26.3f);
  glEnd();
  lit("quad, two edges hidden", 0, 0, 40, 32);
  glBegin(GL_TRIANGLES);
  glEdgeFlag(GL_TRUE);
  glVertex2f(44.3f, 4.3f);
  glVertex2f(76.3f, 6.3f);
  glEdgeFlag(GL_FALSE);
  glVertex2f(60.3f, 28.3f);
  glVertex2f(80.3f, 4.3f);
  glEdgeFlag(GL_TRUE);
  glVertex2f(100.3f, 28.3f);
  glVertex2f(84.3f, 28.3f);
  glEnd();
  lit("triangles", 40, 0, 64, 32);

  /* The current flag FALSE: nothing of the polygon. */
  glEdgeFlag(GL_FALSE);
  glBegin(GL_POLYGON);
  glVertex2f(106.3f, 4.3f); glVertex2f(124.3f, 6.3f); glVertex2f(120.3f, 28.3f);
  glEnd();
  lit("polygon, current flag FALSE", 104, 0, 24, 32);
  glEdgeFlag(GL_TRUE);

  /* Row 2: the array through glDrawArrays, glDrawElements and glArrayElement. */
  static const GLfloat v[] = {4.3f, 36.3f, 36.3f, 38.3f, 34.3f, 60.3f, 6.3f, 58.3f,
                              44.3f, 36.3f, 76.3f, 38.3f, 74.3f, 60.3f, 46.3f, 58.3f};
  static const GLubyte order[] = {5, 6, 7, 4};
  glVertexPointer(2, GL_FLOAT, 0, v);
  glEdgeFlagPointer(0, flags);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glDrawArrays(GL_QUADS, 0, 4);
  lit("glDrawArrays", 0, 32, 40, 32);
  glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, order);
  lit("glDrawElements", 40, 32, 40, 32);
  glTranslatef(80, 0, 0);
  glBegin(GL_POLYGON);
  for (int i = 0; i < 4; i++) glArrayElement(i);
  glEnd();
  lit("glArrayElement", 80, 32, 40, 32);
  glLoadIdentity();
  flag("current after glArrayElement");
  glEdgeFlag(GL_TRUE);

  /* Row 3: points, then a display list holding a flagged pair. */
  glPointSize(3);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glTranslatef(0.3f, 32.3f, 0);
  glDrawArrays(GL_QUADS, 0, 4);
  glDisableClientState(GL_EDGE_FLAG_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  lit("points of the array", 0, 64, 40, 32);
  glLoadIdentity();
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glNewList(1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glVertex2f(44.3f, 68.3f);
  glEdgeFlag(GL_FALSE);
  glVertex2f(76.3f, 70.3f);
  glVertex2f(60.3f, 92.3f);
  glEnd();
  glEndList();
  flag("after compiling");
  glCallList(1);
  lit("list", 40, 64, 40, 32);
  flag("after the list");
  glEdgeFlag(GL_TRUE);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  glBegin(GL_QUADS);
  glVertex2f(84.3f, 68.3f); glVertex2f(84.3f, 92.3f);
  glEdgeFlag(GL_FALSE);
  glVertex2f(124.3f, 90.3f);
  glEdgeFlag(GL_TRUE);
  glVertex2f(122.3f, 70.3f);
  glEnd();
  lit("back face in POINT mode", 80, 64, 48, 32);
  err("drawing");
  glFinish();
  if (argc > 1 && !write_ppm(argv[1], buffer, W, H)) return 3;
  OSMesaDestroyContext(ctx);
  return 0;
}
