/* The depth and stencil buffers OSMesaCreateContextExt(format, depth, stencil, 0, NULL)
 * makes for each pair of sizes asked, and what a missing buffer does: DEPTH_BITS and
 * STENCIL_BITS, a near red square drawn before a far green one with the depth test
 * enabled (without a depth buffer the depth test always passes, GL 1.5 §4.1.5, and the
 * green square covers the red), and a blue square drawn with the stencil test enabled and
 * glStencilFunc(GL_NEVER) (without a stencil buffer the stencil test always passes,
 * §4.1.6), and one depth and one stencil value read back (GL 1.5 §4.3.2: reading a
 * buffer the window lacks is INVALID_OPERATION). Also OSMesaCreateContextAttribs without sizes. One line per context; the
 * outputs on Mesa's OSMesa and on fixedfunc's library must be the same.
 *
 * usage: window_buffers */
#include <GL/osmesa.h>
#include <stdio.h>

static GLubyte buffer[16 * 16 * 4];

static void pixel(const char *what, int x, int y) {
  glFinish();
  const GLubyte *p = buffer + 4 * (y * 16 + x);
  printf(" %s %d %d %d", what, p[0], p[1], p[2]);
}

static void show(OSMesaContext ctx, const char *what) {
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 16, 16)) {
    printf("%-14s no context\n", what);
    return;
  }
  GLint depth = -1, stencil = -1;
  glGetIntegerv(GL_DEPTH_BITS, &depth);
  glGetIntegerv(GL_STENCIL_BITS, &stencil);
  printf("%-14s DEPTH_BITS %d STENCIL_BITS %d", what, depth, stencil);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glColor3f(1, 0, 0);
  glRectf(-0.8f, -0.8f, 0.4f, 0.4f);
  glColor3f(0, 1, 0);
  glBegin(GL_QUADS);
  glVertex3f(-0.4f, -0.4f, 0.5f);
  glVertex3f(0.8f, -0.4f, 0.5f);
  glVertex3f(0.8f, 0.8f, 0.5f);
  glVertex3f(-0.4f, 0.8f, 0.5f);
  glEnd();
  pixel("overlap", 8, 8);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NEVER, 0, 0xFF);
  glColor3f(0, 0, 1);
  glRectf(-1, -1, 1, 1);
  glDisable(GL_STENCIL_TEST);
  pixel("stencil NEVER", 0, 0);
  printf(" err 0x%x", glGetError());
  /* Reading a buffer the window lacks: INVALID_OPERATION, nothing written (§4.3.2). */
  GLfloat z = -1;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
  printf(" depth read %g err 0x%x", z, glGetError());
  GLuint s = 77;
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_INT, &s);
  printf(" stencil read %u err 0x%x\n", s, glGetError());
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

int main(void) {
  static const int sizes[][2] = {{0, 0},  {0, 8},  {1, 0},   {15, 0}, {16, 0}, {17, 0},
                                 {23, 0}, {24, 0}, {32, 0},  {16, 8}, {24, 8}, {1, 1},
                                 {32, 8}, {0, 1},  {24, 16}, {8, 4}};
  for (unsigned i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
    char what[32];
    snprintf(what, sizeof what, "ext(%d, %d)", sizes[i][0], sizes[i][1]);
    show(OSMesaCreateContextExt(OSMESA_RGBA, sizes[i][0], sizes[i][1], 0, NULL), what);
  }
  show(OSMesaCreateContext(OSMESA_RGBA, NULL), "default");
  static const int none[] = {OSMESA_FORMAT, OSMESA_RGBA, 0};
  show(OSMesaCreateContextAttribs(none, NULL), "attribs");
  static const int d16[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 16, 0};
  show(OSMesaCreateContextAttribs(d16, NULL), "attribs d16");
  return 0;
}
