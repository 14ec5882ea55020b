/* Clears of depth alone keep the stencil buffer as it is, whatever wrote it before:
 * stencil-tested draws, scissored and masked stencil clears, full stencil clears, a
 * STENCIL_INDEX pixel rectangle, glCopyPixels of stencil, draws into a framebuffer
 * object in between. After each step, and after a colour-and-depth clear that follows
 * it, prints the stencil and depth values of a row of pixels.
 *
 * usage: stencil_clears */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>

#define W 16
#define H 8

static void row(const char *what) {
  GLubyte s[W];
  GLuint d[W];
  glReadPixels(0, 3, W, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
  glReadPixels(0, 3, W, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, d);
  printf("%-34s stencil", what);
  for (int x = 0; x < W; x++) printf(" %3u", s[x]);
  printf("  depth %08x %08x  err 0x%x\n", d[0], d[W - 1], glGetError());
}

/* A step, then a clear of colour and depth, each printed. */
static void then_clear(const char *what, GLdouble depth) {
  char name[64];
  row(what);
  glClearDepth(depth);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  snprintf(name, sizeof name, "  cleared depth %.2f", depth);
  row(name);
}

/* A quad over x in [x0, x1) (window pixels), at depth z (window, 0..1). */
static void quad(int x0, int x1, float z) {
  float l = 2.0f * x0 / W - 1, r = 2.0f * x1 / W - 1, zz = 2 * z - 1;
  glBegin(GL_QUADS);
  glVertex3f(l, -1, zz);
  glVertex3f(r, -1, zz);
  glVertex3f(r, 1, zz);
  glVertex3f(l, 1, zz);
  glEnd();
}

int main(void) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 2;
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  then_clear("stencil cleared to 0", 1.0);

  /* Stencil-tested draw: REPLACE with 5 over x < 6. */
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 5, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  quad(0, 6, 0.5f);
  glDisable(GL_STENCIL_TEST);
  then_clear("REPLACE 5 over x < 6", 0.25);

  /* A draw with the test off leaves stencil alone; depth written. */
  quad(4, 12, 0.1f);
  then_clear("untested draw over 4 <= x < 12", 0.75);

  /* Full stencil clear (value masked to 8 bits), then depth clears. */
  glClearStencil(0x107);
  glClear(GL_STENCIL_BUFFER_BIT);
  then_clear("stencil cleared to 0x107", 1.0);
  then_clear("again", 0.5);

  /* A scissored stencil clear. */
  glEnable(GL_SCISSOR_TEST);
  glScissor(8, 0, 4, H);
  glClearStencil(9);
  glClear(GL_STENCIL_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  then_clear("scissored clear to 9 at 8 <= x < 12", 1.0);

  /* A stencil clear through a partial write mask. */
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glStencilMask(0x0F);
  glClearStencil(0xFF);
  glClear(GL_STENCIL_BUFFER_BIT);
  glStencilMask(0xFF);
  then_clear("0 then 0xFF through mask 0x0F", 1.0);

  /* A depth clear with depth writes off clears no depth. */
  glDepthMask(GL_FALSE);
  glClearDepth(0.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDepthMask(GL_TRUE);
  row("depth clear with depth writes off");

  /* A STENCIL_INDEX rectangle, then a copy of it. */
  glClearStencil(2);
  glClear(GL_STENCIL_BUFFER_BIT);
  GLubyte values[4 * H];
  for (int i = 0; i < 4 * H; i++) values[i] = (GLubyte)(40 + i % 4);
  glWindowPos2i(1, 0);
  glDrawPixels(4, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, values);
  then_clear("STENCIL_INDEX rectangle at 1 <= x < 5", 1.0);
  glWindowPos2i(10, 0);
  glCopyPixels(1, 0, 4, H, GL_STENCIL);
  then_clear("copied to 10 <= x < 14", 1.0);

  /* A framebuffer object's stencil is its own: the window's stays known. */
  glClearStencil(6);
  glClear(GL_STENCIL_BUFFER_BIT);
  GLuint fbo, rb[2];
  glGenFramebuffersEXT(1, &fbo);
  glGenRenderbuffersEXT(2, rb);
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fbo);
  glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, rb[0]);
  glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_RGBA8, W, H);
  glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT,
                               GL_RENDERBUFFER_EXT, rb[0]);
  glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, rb[1]);
  glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH24_STENCIL8_EXT, W, H);
  glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT,
                               GL_RENDERBUFFER_EXT, rb[1]);
  glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_STENCIL_ATTACHMENT_EXT,
                               GL_RENDERBUFFER_EXT, rb[1]);
  glClearStencil(1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 3, 0xFF);
  quad(0, 8, 0.5f);
  glDisable(GL_STENCIL_TEST);
  glClear(GL_DEPTH_BUFFER_BIT);
  row("framebuffer object: 3 over x < 8");
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
  then_clear("window after it (cleared to 6)", 0.5);

  /* A new buffer of another size: its stencil starts cleared by the program. */
  GLubyte *other = calloc(W * 2 * H, 4);
  if (!other || !OSMesaMakeCurrent(ctx, other, GL_UNSIGNED_BYTE, W * 2, H)) return 2;
  glClearStencil(4);
  glClear(GL_STENCIL_BUFFER_BIT);
  then_clear("new buffer, stencil cleared to 4", 1.0);
  OSMesaDestroyContext(ctx);
  free(buf);
  free(other);
  return 0;
}
