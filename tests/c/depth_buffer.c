/* OSMesaGetDepthBuffer as Mesa's OSMesa answers it: no buffer (0, sizes 0) without a
 * depth buffer; 2 bytes a value for 16-bit depth; 4 for 24-bit, the depth in the low 24
 * bits and the stencil in the top byte. The pointer stays the same from call to call and
 * its values follow what was drawn and cleared as of the last glFinish. One block per
 * context; the outputs on Mesa's OSMesa and on fixedfunc's library must be the same.
 *
 * usage: depth_buffer */
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

static unsigned raw(const void *p, GLint bpv) {
  return bpv == 2 ? ((const GLushort *)p)[0] : ((const GLuint *)p)[0];
}

static void show(int depth, int stencil) {
  static GLubyte buffer[16 * 16 * 4];
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, depth, stencil, 0, NULL);
  if (!c || !OSMesaMakeCurrent(c, buffer, GL_UNSIGNED_BYTE, 16, 16)) return;
  GLint w = -1, h = -1, bpv = -1;
  void *p = (void *)1;
  GLboolean ok = OSMesaGetDepthBuffer(c, &w, &h, &bpv, &p);
  printf("ext(%d, %d): %d %dx%d bytes %d null %d\n", depth, stencil, ok, w, h, bpv, p == NULL);
  if (ok && p) {
    printf("  initial 0x%x\n", raw(p, bpv));
    glClearDepth(0.75);
    glClearStencil(0x5A);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glFinish();
    printf("  cleared to 0.75 and 0x5A: 0x%x\n", raw(p, bpv));
    void *p2 = NULL;
    OSMesaGetDepthBuffer(c, &w, &h, &bpv, &p2);
    printf("  again: same pointer %d 0x%x\n", p2 == p, raw(p2, bpv));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glBegin(GL_QUADS);
    glVertex3f(-1, -1, 0);
    glVertex3f(1, -1, 0);
    glVertex3f(1, 1, 0);
    glVertex3f(-1, 1, 0);
    glEnd();
    printf("  drawn at 0.5, no glFinish: 0x%x\n", raw(p, bpv));
    glFinish();
    printf("  glFinish: 0x%x\n", raw(p, bpv));
  }
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(c);
}

int main(void) {
  show(0, 0);
  show(0, 8);
  show(16, 0);
  show(24, 0);
  show(24, 8);
  return 0;
}
