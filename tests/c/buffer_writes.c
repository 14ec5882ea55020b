/* When glFinish and glFlush write the image to the caller's buffer: only when something
 * was drawn, cleared or copied since the last write (Mesa's OSMesa writes its front
 * buffer only then), so bytes the program puts in its buffer stay until it draws. Also
 * RED_BITS … ALPHA_BITS of GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT and GL_FLOAT buffers
 * made current in turn on one context. The outputs on Mesa's OSMesa and on fixedfunc's
 * library must be the same.
 *
 * usage: buffer_writes */
#include <GL/osmesa.h>
#include <stdio.h>
#include <string.h>

static void bits(const char *what) {
  GLint r = -1, g = -1, b = -1, a = -1;
  glGetIntegerv(GL_RED_BITS, &r);
  glGetIntegerv(GL_GREEN_BITS, &g);
  glGetIntegerv(GL_BLUE_BITS, &b);
  glGetIntegerv(GL_ALPHA_BITS, &a);
  printf("%s: bits %d %d %d %d\n", what, r, g, b, a);
}

int main(void) {
  static GLubyte b[16 * 16 * 4], b2[16 * 16 * 4];
  static GLushort s[8 * 8 * 4];
  static GLfloat f[8 * 8 * 4];
  memset(b, 0xAB, sizeof b);
  memset(b2, 0xCD, sizeof b2);
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  OSMesaContext c2 = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!c || !c2 || !OSMesaMakeCurrent(c, b, GL_UNSIGNED_BYTE, 16, 16)) return 1;
  printf("made current: %x %x\n", b[0], b[1023]);
  glGetError();
  glFinish();
  glFlush();
  printf("glFinish, nothing drawn: %x %x\n", b[0], b[1023]);
  glEnable(GL_DEPTH_TEST);
  glColor3f(1, 0, 0);
  glFinish();
  printf("state changed: %x %x\n", b[0], b[1023]);
  OSMesaMakeCurrent(c2, b2, GL_UNSIGNED_BYTE, 16, 16);
  printf("switched: b %x b2 %x\n", b[0], b2[0]);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  printf("cleared, no glFinish: b2 %x %x\n", b2[0], b2[1]);
  glFinish();
  printf("glFinish: b2 %x %x\n", b2[0], b2[1]);
  memset(b2, 0x40, sizeof b2);
  glFinish();
  printf("program wrote, glFinish: b2 %x %x\n", b2[0], b2[1]);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 1, 1);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  printf("scissored clear, glFlush: px0 %x %x px1 %x %x\n", b2[0], b2[1], b2[4], b2[5]);
  glDisable(GL_SCISSOR_TEST);
  bits("GL_UNSIGNED_BYTE");

  for (int i = 0; i < 8 * 8 * 4; i++) f[i] = -3;
  OSMesaMakeCurrent(c, f, GL_FLOAT, 8, 8);
  bits("GL_FLOAT");
  glFinish();
  printf("GL_FLOAT made current, glFinish: %g\n", f[0]);
  glClearColor(0.25f, 0.5f, 0.75f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  printf("GL_FLOAT cleared: %g %g %g %g\n", f[0], f[1], f[2], f[3]);
  memset(s, 0x11, sizeof s);
  OSMesaMakeCurrent(c, s, GL_UNSIGNED_SHORT, 8, 8);
  bits("GL_UNSIGNED_SHORT");
  glFinish();
  printf("GL_UNSIGNED_SHORT made current, glFinish: %u\n", s[0]);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  printf("GL_UNSIGNED_SHORT cleared: %u %u %u %u\n", s[0], s[1], s[2], s[3]);
  OSMesaMakeCurrent(c, b, GL_UNSIGNED_BYTE, 16, 16);
  bits("GL_UNSIGNED_BYTE again");
  OSMesaDestroyContext(c);
  OSMesaDestroyContext(c2);
  return 0;
}
