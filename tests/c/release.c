/* OSMesaMakeCurrent(NULL, NULL, 0, 0, 0) releases the current context and returns
 * GL_TRUE: the image drawn so far reaches the buffer first (as at a switch to another
 * context), GL calls then do nothing (glGetError 0, glGetString NULL), and the context
 * made current again keeps its state. The outputs on Mesa's OSMesa and on fixedfunc's
 * library must be the same.
 *
 * usage: release */
#include <GL/osmesa.h>
#include <stdio.h>
#include <string.h>

int main(void) {
  static GLubyte b[16 * 16 * 4], b2[16 * 16 * 4];
  memset(b, 0xAB, sizeof b);
  memset(b2, 0xCD, sizeof b2);
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  OSMesaContext c2 = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  if (!c || !c2 || !OSMesaMakeCurrent(c, b, GL_UNSIGNED_BYTE, 16, 16)) return 1;
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  printf("cleared, no glFinish: %x %x\n", b[0], b[1]);
  GLboolean r = OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  printf("release: %d current %d buffer %x %x\n", r, OSMesaGetCurrentContext() != NULL, b[0],
         b[1]);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  printf("GL without a context: err 0x%x string %d buffer %x %x\n", glGetError(),
         glGetString(GL_VENDOR) != NULL, b[0], b[1]);
  r = OSMesaMakeCurrent(c, b, GL_UNSIGNED_BYTE, 16, 16);
  GLfloat cc[4];
  glGetFloatv(GL_COLOR_CLEAR_VALUE, cc);
  printf("current again: %d clear colour %g %g %g\n", r, cc[0], cc[1], cc[2]);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  OSMesaMakeCurrent(c2, b2, GL_UNSIGNED_BYTE, 16, 16);
  printf("switch after a clear: b %x %x %x b2 %x\n", b[0], b[1], b[2], b2[0]);
  r = OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  printf("release again: %d current %d\n", r, OSMesaGetCurrentContext() != NULL);
  r = OSMesaMakeCurrent(NULL, b, GL_UNSIGNED_BYTE, 16, 16);
  printf("NULL context with a buffer: %d\n", r);
  OSMesaDestroyContext(c);
  OSMesaDestroyContext(c2);
  return 0;
}
