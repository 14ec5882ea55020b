/* Display lists: compiled and compiled-and-executed lists, nesting, glCallLists with a
 * list base, vertex arrays read at compile time, a list that raises an error when it
 * runs, glGenLists/glIsList/glDeleteLists, glCallList(0) (INVALID_VALUE on Mesa). Prints
 * what glGetError and glIsList give after each step and writes the image.
 *
 * usage: lists OUT.ppm */
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

#include "gl_resolve.h"

#define W 160
#define H 160

static void report(const char *step) { printf("%-34s 0x%04x\n", step, (unsigned)glGetError()); }

int main(int argc, char **argv) {
  if (argc < 2) return 2;
  static GLubyte buffer[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) return 1;
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, 4, 0, 4, -1, 1);
  glMatrixMode(GL_MODELVIEW);

  GLuint base = glGenLists(4);
  printf("glGenLists(4) gave a name: %d\n", base != 0);
  printf("glIsList(base + 3) %d, glIsList(base + 4) %d\n", glIsList(base + 3), glIsList(base + 4));
  report("after glGenLists");

  /* base: a unit square whose colour changes after its first vertex. */
  glNewList(base, GL_COMPILE);
  glBegin(GL_QUADS);
  glVertex2f(0.1f, 0.1f);
  glColor3f(1, 0.5f, 0);
  glVertex2f(0.9f, 0.1f);
  glVertex2f(0.9f, 0.9f);
  glVertex2f(0.1f, 0.9f);
  glEnd();
  glEndList();
  report("compile a square");

  /* base + 1: move right, then the square, nested. */
  glNewList(base + 1, GL_COMPILE);
  glTranslatef(1, 0, 0);
  glCallList(base);
  glEndList();

  /* base + 2: a triangle from a vertex array, read now; the array changes afterwards. */
  GLfloat tri[] = {0.1f, 0.1f, 0.9f, 0.1f, 0.5f, 0.9f};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, tri);
  glNewList(base + 2, GL_COMPILE_AND_EXECUTE);
  glColor3f(0, 1, 0);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEndList();
  tri[4] = 0.1f;
  tri[5] = 0.5f;
  report("compile and execute a triangle");

  /* base + 3: a bad call, recorded; the error comes when the list runs. */
  glNewList(base + 3, GL_COMPILE);
  glEnable(0x1234);
  glColor3f(0, 0, 1);
  glEndList();
  report("compile a bad call");

  glColor3f(1, 1, 1);
  glLoadIdentity();
  glTranslatef(0, 1, 0);
  glCallList(base);
  glCallList(base + 1);
  glCallList(base + 1);
  report("call the squares");

  glLoadIdentity();
  glTranslatef(0, 2, 0);
  GLubyte offsets[] = {1, 2, 3, 2};
  glListBase(base);
  glCallLists(4, GL_UNSIGNED_BYTE, offsets);
  report("glCallLists through the base");

  glLoadIdentity();
  glTranslatef(0, 3, 0);
  glCallList(base);
  report("a square after the error");

  /* Names as 2, 3 and 4 big-endian bytes (GL 1.5 §5.4), from the base set above. */
  const GLubyte names2[] = {0, 1}, names3[] = {0, 0, 3}, names4[] = {0, 0, 0, 1};
  glCallLists(1, GL_2_BYTES, names2);
  report("glCallLists GL_2_BYTES");
  glCallLists(1, GL_3_BYTES, names3);
  report("glCallLists GL_3_BYTES");
  glCallLists(1, GL_4_BYTES, names4);
  report("glCallLists GL_4_BYTES");
  glListBase(0);

  glDeleteLists(base + 1, 2);
  printf("after delete: glIsList %d %d %d\n", glIsList(base), glIsList(base + 1), glIsList(base + 3));
  glCallList(base + 1);
  report("calling a deleted list");
  glCallList(0);
  report("glCallList(0)");

  glNewList(0, GL_COMPILE);
  report("glNewList(0)");
  glNewList(base + 5, GL_COMPILE);
  glNewList(base + 6, GL_COMPILE);
  report("nested glNewList");
  glEndList();
  glEndList();
  report("glEndList twice");

  glFinish();
  int ok = write_ppm(argv[1], buffer, W, H);
  OSMesaDestroyContext(ctx);
  return ok ? 0 : 1;
}
