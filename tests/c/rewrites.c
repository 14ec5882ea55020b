/* Client arrays rewritten between draws: GL reads a client array when the draw is called
 * (GL 1.5 §2.8), so a draw after the program changed the bytes in place — same pointer,
 * same count — must show the new bytes, and a draw of unchanged bytes the old ones. Six
 * panels, each a draw from the same three arrays:
 *   0: the arrays as first filled (a red triangle, glDrawElements);
 *   1: the same draw again, nothing changed;
 *   2: the colours rewritten in place (green);
 *   3: one position rewritten in place (the triangle's apex moved down);
 *   4: the indices rewritten in place (the triangle drawn through the fourth vertex);
 *   5: glDrawArrays of the first three vertices, then a colour rewritten and drawn again
 *      over it (blue apex).
 *
 * usage: rewrites OUT.ppm */
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
  glClear(GL_COLOR_BUFFER_BIT);

  GLfloat xyz[] = {-0.9f, -0.9f, 0, 0.9f, -0.9f, 0, 0, 0.9f, 0, -0.9f, 0.9f, 0};
  GLubyte rgba[] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
  GLushort idx[] = {0, 1, 2};
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, xyz);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, rgba);

  panel(0);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, idx);
  panel(1);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, idx);

  for (int v = 0; v < 4; v++) rgba[4 * v] = 0, rgba[4 * v + 1] = 255;
  panel(2);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, idx);

  xyz[7] = 0.0f;
  panel(3);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, idx);

  idx[2] = 3;
  panel(4);
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, idx);

  panel(5);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  rgba[8] = 0, rgba[9] = 0, rgba[10] = 255;
  glDrawArrays(GL_TRIANGLES, 0, 3);

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
