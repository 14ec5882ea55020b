/* glClearDepth takes a double, and Mesa keeps it as one: 0.3 clears a 24-bit depth buffer
 * to 0x4CCCCC (0.3 rounded to a float first would give 0x4CCCCD) and DEPTH_CLEAR_VALUE
 * reads back the double. For values in [0, 1] and outside, prints the cleared value read
 * as GL_UNSIGNED_INT and the query through glGetDoublev, glGetFloatv and glGetIntegerv.
 *
 * usage: clear_depth */
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

int main(void) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(4 * 4, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 4, 4)) return 2;
  static const double values[] = {0.3, 0.1, 0.7, 1.0 / 3, 0.123456789, 0.9, 0.5, -0.25, 1.5};
  for (unsigned i = 0; i < sizeof values / sizeof values[0]; i++) {
    glClearDepth(values[i]);
    glClear(GL_DEPTH_BUFFER_BIT);
    GLuint depth = 0;
    glReadPixels(1, 1, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &depth);
    GLdouble d = -1;
    GLfloat f = -1;
    GLint n = -1;
    glGetDoublev(GL_DEPTH_CLEAR_VALUE, &d);
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, &f);
    glGetIntegerv(GL_DEPTH_CLEAR_VALUE, &n);
    printf("glClearDepth(%.17g)  cleared 0x%08x  double %.17g  float %.9g  int %d  err 0x%x\n",
           values[i], depth, d, f, n, glGetError());
  }
  OSMesaDestroyContext(ctx);
  free(buf);
  return 0;
}
