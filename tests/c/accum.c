/* The accumulation buffer as the Red Book's programs used it: a motion-blurred scene made
 * of N jittered renders, each added with glAccum(GL_ACCUM, 1/N) and returned with
 * glAccum(GL_RETURN, 1); then LOAD, ADD, MULT, the clear, the scissor box and the colour
 * mask on parts of the window, the errors and the glGet answers, one line each. Run on
 * Mesa's OSMesa and on fixedfunc's library, the printed lines must be the same and the
 * images match.
 *
 * usage: accum [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>
#include "report.h"

#define W 64
#define H 64
#define N 8

static void floats(const char *what, GLenum pname) {
  GLfloat v[4] = {-7, -7, -7, -7};
  glGetFloatv(pname, v);
  printf("%-40s %g %g %g %g  err 0x%x\n", what, v[0], v[1], v[2], v[3], glGetError());
}

static void pixel(const char *what, int x, int y) {
  GLubyte p[4];
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  printf("%-40s %d %d %d %d  err 0x%x\n", what, p[0], p[1], p[2], p[3], glGetError());
}

static void scene(float dx) {
  glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0.8f, 0.2f); glVertex2f(-0.8f + dx, -0.6f);
  glColor3f(0.2f, 1, 0.4f); glVertex2f(-0.2f + dx, -0.6f);
  glColor3f(0.3f, 0.4f, 1); glVertex2f(-0.5f + dx, 0.2f);
  glEnd();
  glColor3f(0.9f, 0.3f, 0.6f);
  glRectf(0.1f, 0.3f - dx, 0.6f, 0.8f - dx);
}

int main(int argc, char **argv) {
  static GLubyte buffer[W * H * 4], small[4 * 4 * 4];
  OSMesaContext none = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!none || !OSMesaMakeCurrent(none, small, GL_UNSIGNED_BYTE, 4, 4)) return 1;
  ints("no accum: ACCUM_RED_BITS", GL_ACCUM_RED_BITS);
  glAccum(GL_ACCUM, 1.0f);
  err("no accum: glAccum");
  glAccum(GL_ZERO, 1.0f);
  err("no accum: glAccum(GL_ZERO)");
  glClear(GL_ACCUM_BUFFER_BIT);
  err("no accum: glClear(ACCUM_BUFFER_BIT)");
  OSMesaDestroyContext(none);

  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 16, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) return 2;
  ints("ACCUM_RED_BITS", GL_ACCUM_RED_BITS);
  ints("ACCUM_GREEN_BITS", GL_ACCUM_GREEN_BITS);
  ints("ACCUM_BLUE_BITS", GL_ACCUM_BLUE_BITS);
  ints("ACCUM_ALPHA_BITS", GL_ACCUM_ALPHA_BITS);
  floats("ACCUM_CLEAR_VALUE", GL_ACCUM_CLEAR_VALUE);
  glClearAccum(2.0f, -3.0f, 0.5f, -0.25f);
  floats("ACCUM_CLEAR_VALUE clamped", GL_ACCUM_CLEAR_VALUE);
  glPushAttrib(GL_ACCUM_BUFFER_BIT);
  glClearAccum(0, 0, 0, 0);
  glPopAttrib();
  floats("ACCUM_CLEAR_VALUE popped", GL_ACCUM_CLEAR_VALUE);
  glAccum(GL_ZERO, 1.0f);
  err("glAccum(GL_ZERO)");
  glBegin(GL_POINTS);
  glAccum(GL_ACCUM, 1.0f);
  glEnd();
  err("glAccum inside glBegin");

  GLuint fb, rb;
  glGenFramebuffers(1, &fb);
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 4);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  ints("fbo: ACCUM_RED_BITS", GL_ACCUM_RED_BITS);
  glAccum(GL_ACCUM, 1.0f);
  err("fbo: glAccum");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fb);
  glDeleteRenderbuffers(1, &rb);

  /* One pixel's arithmetic: the sums, LOAD, ADD, MULT and RETURN's scale. */
  glClearAccum(0, 0, 0, 0);
  glClear(GL_ACCUM_BUFFER_BIT);
  glClearColor(1, 0.5f, 0.25f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glAccum(GL_ACCUM, 0.5f);
  glClearColor(0, 1, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glAccum(GL_ACCUM, 0.5f);
  glAccum(GL_RETURN, 1.0f);
  pixel("two frames at 0.5", 0, 0);
  glClearColor(0.6f, 0.2f, 0.4f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glAccum(GL_LOAD, 0.5f);
  glAccum(GL_RETURN, 2.0f);
  pixel("LOAD 0.5, RETURN 2", 0, 0);
  glClearAccum(0.1f, 0.2f, 0.3f, 0.4f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_ADD, 0.25f);
  glAccum(GL_RETURN, 1.0f);
  pixel("clear, ADD 0.25", 0, 0);
  glAccum(GL_ADD, 1.5f);
  glAccum(GL_RETURN, 1.0f);
  pixel("ADD 1.5 wraps", 0, 0);
  glClearAccum(0.5f, 0.5f, 0.5f, 0.5f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_MULT, 0.5f);
  glAccum(GL_RETURN, 1.0f);
  pixel("MULT 0.5", 0, 0);
  glAccum(GL_MULT, -1.0f);
  glAccum(GL_RETURN, -1.0f);
  pixel("MULT -1, RETURN -1", 0, 0);
  glClearAccum(-0.5f, 0.5f, 0.2f, 0.8f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_RETURN, -1.0f);
  pixel("clear -0.5, RETURN -1", 0, 0);
  err("arithmetic");

  /* The image: a motion blur of N renders. */
  glClearAccum(0, 0, 0, 0);
  glClear(GL_ACCUM_BUFFER_BIT);
  for (int i = 0; i < N; i++) {
    scene(0.05f * (float)i);
    glAccum(GL_ACCUM, 1.0f / N);
  }
  glAccum(GL_RETURN, 1.0f);
  err("motion blur");
  pixel("blurred triangle", 20, 20);
  pixel("blurred rectangle", 45, 45);

  /* The scissor box limits the clear and the ops; RETURN writes through the mask. */
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 16, 64);
  glClearAccum(0.25f, 0.5f, 0.75f, 1.0f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glScissor(0, 0, 32, 16);
  glAccum(GL_MULT, 2.0f);
  glScissor(0, 0, 64, 8);
  glAccum(GL_ADD, -0.2f);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glAccum(GL_RETURN, 0.9f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  err("scissor and mask");
  pixel("cleared, MULT 2, ADD -0.2", 4, 4);
  pixel("cleared, MULT 2", 4, 12);
  pixel("cleared", 4, 40);
  pixel("blur, ADD -0.2", 40, 4);
  pixel("blur", 45, 45);
  glFinish();
  if (argc > 1 && !write_ppm(argv[1], buffer, W, H)) return 3;
  OSMesaDestroyContext(ctx);
  return 0;
}
