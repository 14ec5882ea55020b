/* glReadPixels of rectangles that reach beyond the window, as Mesa's OSMesa answers them:
 * Mesa clips the read to the buffer and writes nothing of the pixels outside, which keep
 * what the program's memory held (GL leaves them undefined). Colour over each corner and
 * edge, with and without PACK_ROW_LENGTH/SKIP_PIXELS/SKIP_ROWS/ALIGNMENT, depth and
 * stencil over an edge, and a rectangle wholly outside; then the same for a framebuffer
 * object bound for reading, clipped to its smallest attachment (a 12×10 texture beside a
 * 16×16 depth renderbuffer). Memory is prefilled with 0xEE; each read prints its bytes as
 * a hash and the first bytes of each row.
 *
 * usage: read_outside */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 32
#define H 32

static unsigned long hash(const GLubyte *p, size_t n) {
  unsigned long h = 1469598103934665603UL;
  for (size_t i = 0; i < n; i++) h = (h ^ p[i]) * 1099511628211UL;
  return h;
}

static void report(const char *what, const GLubyte *mem, size_t n, size_t row) {
  printf("%-34s hash %016lx  err 0x%x  rows:", what, hash(mem, n), glGetError());
  for (size_t r = 0; r * row < n && r < 4; r++) printf(" %02x%02x%02x%02x", mem[r * row],
                                                        mem[r * row + 1], mem[r * row + 2],
                                                        mem[r * row + 3]);
  printf("\n");
}

static void colour(const char *what, int x, int y, int w, int h) {
  static GLubyte mem[64 * 64 * 4];
  memset(mem, 0xEE, sizeof mem);
  glReadPixels(x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, mem);
  report(what, mem, sizeof mem, (size_t)w * 4);
}

int main(void) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 2;
  glClearColor(1, 0, 0, 1);
  glClearDepth(0.25);
  glClearStencil(7);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, W / 2, H / 2);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);

  colour("top right corner", 30, 30, 4, 4);
  colour("bottom left corner", -2, -3, 6, 5);
  colour("left edge", -5, 10, 8, 2);
  colour("wider than the window", -4, 4, 40, 3);
  colour("wholly outside", 40, 40, 4, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, 10);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 2);
  glPixelStorei(GL_PACK_SKIP_ROWS, 1);
  colour("bottom left, row length 10, skips", -2, -3, 6, 5);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);
  {
    static GLubyte mem[64 * 64 * 4];
    memset(mem, 0xEE, sizeof mem);
    glReadPixels(29, 5, 5, 3, GL_RGB, GL_UNSIGNED_BYTE, mem);
    report("RGB, alignment 8, right edge", mem, sizeof mem, 16);
  }
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  {
    static GLuint depth[16];
    memset(depth, 0xEE, sizeof depth);
    glReadPixels(-1, 0, 2, 2, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    report("depth over the left edge", (const GLubyte *)depth, sizeof depth, 8);
    static GLubyte stencil[16];
    memset(stencil, 0xEE, sizeof stencil);
    glReadPixels(31, 31, 2, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
    report("stencil over the top right", stencil, sizeof stencil, 4);
  }
  {
    GLuint fb, tex, rb;
    glGenFramebuffersEXT(1, &fb);
    glGenTextures(1, &tex);
    glGenRenderbuffersEXT(1, &rb);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 12, 10, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, rb);
    glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, 16, 16);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, tex, 0);
    glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT,
                                 rb);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    colour("object: right edge", 10, 2, 4, 2);
    colour("object: top right corner", 11, 9, 3, 3);
    colour("object: bottom left corner", -1, -2, 3, 3);
    colour("object: wider than it", -2, 4, 16, 1);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    colour("window again: right edge", 30, 2, 4, 2);
  }
  OSMesaDestroyContext(ctx);
  free(buf);
  return 0;
}
