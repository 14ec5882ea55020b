/* glBlitFramebuffer and glBlitFramebufferEXT (EXT_framebuffer_blit, GL 3.0 §4.3.3) as the
 * programs of 2006–2010 used them: copies between the window and framebuffer objects
 * through the separate READ_FRAMEBUFFER and DRAW_FRAMEBUFFER bindings, scaled with
 * NEAREST and LINEAR, flipped, under the scissor test, of colour, depth and stencil; and
 * the errors of bad calls (mask bits, filters, format mismatches, incomplete framebuffers),
 * one line each. Run on Mesa's OSMesa and on fixedfunc's library, the printed lines must
 * be the same and the images match.
 *
 * usage: blit [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>
#include "report.h"
#include <string.h>

#define W 64
#define H 64

static void pixel(const char *what, int x, int y) {
  GLubyte p[4] = {0};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  printf("%-40s %d %d %d %d  err 0x%x\n", what, p[0], p[1], p[2], p[3], glGetError());
}

static void depth(const char *what, int x, int y) {
  GLfloat z = -1;
  glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
  printf("%-40s %.4f  err 0x%x\n", what, z, glGetError());
}

static void stencil(const char *what, int x, int y) {
  GLubyte s = 99;
  glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
  printf("%-40s %d  err 0x%x\n", what, s, glGetError());
}

static void blit(const char *what, GLint sx0, GLint sy0, GLint sx1, GLint sy1, GLint dx0,
                 GLint dy0, GLint dx1, GLint dy1, GLbitfield mask, GLenum filter) {
  glBlitFramebuffer(sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1, mask, filter);
  err(what);
}

/* A renderbuffer of `format`, w × h. */
static GLuint storage(GLenum format, int w, int h) {
  GLuint rb = 0;
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, format, w, h);
  return rb;
}

/* A framebuffer with `color` (0: none) and `depth` at DEPTH (and STENCIL when
 * `packed`). */
static GLuint framebuffer(GLuint color, GLuint depth_rb, int packed) {
  GLuint fb = 0;
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  if (color)
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  if (depth_rb)
    glFramebufferRenderbuffer(GL_FRAMEBUFFER,
                              packed ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                              GL_RENDERBUFFER, depth_rb);
  return fb;
}

/* The window's scene: four coloured quadrants, a horizontal grey ramp along the top
 * and a triangle at depths from 0.25 to 0.75 that writes stencil 5. */
static void scene(void) {
  glViewport(0, 0, W, H);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClearDepth(1);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor3f(1, 0, 0); glRecti(0, 0, 32, 24);
  glColor3f(0, 1, 0); glRecti(32, 0, 64, 24);
  glColor3f(0, 0, 1); glRecti(0, 24, 32, 48);
  glColor3f(1, 1, 0); glRecti(32, 24, 64, 48);
  glBegin(GL_QUADS);
  glColor3f(0, 0, 0); glVertex2i(0, 48); glColor3f(1, 1, 1); glVertex2i(64, 48);
  glColor3f(1, 1, 1); glVertex2i(64, 64); glColor3f(0, 0, 0); glVertex2i(0, 64);
  glEnd();
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 5, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 1);
  glVertex3f(4, 4, 0.5f); glVertex3f(60, 4, 0); glVertex3f(4, 60, -0.5f);
  glEnd();
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
}

int main(int argc, char **argv) {
  static GLubyte buffer[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) return 1;

  const char *ext = (const char *)glGetString(GL_EXTENSIONS);
  printf("%-40s %d\n", "GL_EXT_framebuffer_blit", ext && strstr(ext, "GL_EXT_framebuffer_blit") != NULL);
  ints("draw framebuffer binding", GL_DRAW_FRAMEBUFFER_BINDING);
  ints("read framebuffer binding", GL_READ_FRAMEBUFFER_BINDING);
  ints("draw binding (EXT name)", GL_DRAW_FRAMEBUFFER_BINDING_EXT);
  ints("read binding (EXT name)", GL_READ_FRAMEBUFFER_BINDING_EXT);

  /* The objects: small (32x32 RGBA8 + D24S8), big (64x64 RGBA8 + D24S8), and the
   * mismatches and incomplete ones. */
  GLuint small_c = storage(GL_RGBA8, 32, 32), small_z = storage(GL_DEPTH24_STENCIL8, 32, 32);
  GLuint big_c = storage(GL_RGBA8, W, H), big_z = storage(GL_DEPTH24_STENCIL8, W, H);
  GLuint d16 = storage(GL_DEPTH_COMPONENT16, W, H), d32f = storage(GL_DEPTH_COMPONENT32F, W, H);
  GLuint d24 = storage(GL_DEPTH_COMPONENT24, W, H), rgba16f = storage(GL_RGBA16F, W, H);
  GLuint empty_rb = storage(GL_RGBA8, 0, 0);
  GLuint small = framebuffer(small_c, small_z, 1), big = framebuffer(big_c, big_z, 1);
  GLuint fb16 = framebuffer(0, d16, 0), fb32f = framebuffer(0, d32f, 0);
  GLuint fb24 = framebuffer(big_c, d24, 0), fbf = framebuffer(rgba16f, 0, 0);
  GLuint broken = framebuffer(empty_rb, 0, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  err("made");
  glBindFramebuffer(GL_READ_FRAMEBUFFER, small);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, big);
  ints("draw binding after separate binds", GL_DRAW_FRAMEBUFFER_BINDING);
  ints("read binding after separate binds", GL_READ_FRAMEBUFFER_BINDING);
  ints("framebuffer binding (= draw)", GL_FRAMEBUFFER_BINDING);

  /* Errors. */
  blit("mask ACCUM_BUFFER_BIT", 0, 0, 8, 8, 0, 0, 8, 8, GL_ACCUM_BUFFER_BIT, GL_NEAREST);
  blit("mask 0x1", 0, 0, 8, 8, 0, 0, 8, 8, 0x1, GL_NEAREST);
  blit("mask 0", 0, 0, 8, 8, 0, 0, 8, 8, 0, GL_NEAREST);
  blit("filter LINEAR, depth", 0, 0, 8, 8, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT, GL_LINEAR);
  blit("filter LINEAR, stencil", 0, 0, 8, 8, 0, 0, 8, 8, GL_STENCIL_BUFFER_BIT, GL_LINEAR);
  blit("filter LINEAR, colour", 0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  blit("filter NEAREST_MIPMAP_NEAREST", 0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT,
       GL_NEAREST_MIPMAP_NEAREST);
  blit("filter SCALED_RESOLVE_FASTEST", 0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT,
       GL_SCALED_RESOLVE_FASTEST_EXT);
  blit("filter TEXTURE_2D", 0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_TEXTURE_2D);
  blit("bad filter and bad mask", 0, 0, 8, 8, 0, 0, 8, 8, 0x1, GL_TEXTURE_2D);
  blit("LINEAR depth and bad mask", 0, 0, 8, 8, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT | 0x1,
       GL_LINEAR);
  blit("empty source rectangle", 4, 4, 4, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  blit("negative coordinates", -8, -8, 8, 8, -4, -4, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, broken);
  blit("incomplete read framebuffer", 0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  blit("incomplete read, bad mask", 0, 0, 8, 8, 0, 0, 8, 8, 0x1, GL_NEAREST);
  blit("incomplete read, bad filter", 0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_TEXTURE_2D);
  blit("incomplete read, mask 0", 0, 0, 8, 8, 0, 0, 8, 8, 0, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, small);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, broken);
  blit("incomplete draw framebuffer", 0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb16);
  blit("depth D24S8 into D16", 0, 0, 8, 8, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  blit("colour into depth-only D16", 0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  blit("stencil into D16 (no stencil)", 0, 0, 8, 8, 0, 0, 8, 8, GL_STENCIL_BUFFER_BIT, GL_NEAREST);
  blit("depth+stencil into D16", 0, 0, 8, 8, 0, 0, 8, 8,
       GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb32f);
  blit("depth D24S8 into D32F", 0, 0, 8, 8, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb24);
  blit("depth D24S8 into D24", 0, 0, 8, 8, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  blit("stencil D24S8 into D24", 0, 0, 8, 8, 0, 0, 8, 8, GL_STENCIL_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbf);
  blit("colour RGBA8 into RGBA16F", 0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fb16);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, small);
  blit("depth D16 into D24S8", 0, 0, 8, 8, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb16);
  blit("depth window into D16", 0, 0, 8, 8, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb32f);
  blit("depth window into D32F", 0, 0, 8, 8, 0, 0, 8, 8, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, big);
  glReadBuffer(GL_NONE);
  blit("colour with read buffer NONE", 0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glReadBuffer(GL_FRONT);
  glDrawBuffer(GL_NONE);
  blit("colour with draw buffer NONE", 0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glBegin(GL_POINTS);
  glBlitFramebuffer(0, 0, 8, 8, 0, 0, 8, 8, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glEnd();
  err("inside begin/end");

  /* The window's scene, copied into `big` whole (colour, depth and stencil). */
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  scene();
  err("scene");
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, big);
  blit("window into big, all buffers", 0, 0, W, H, 0, 0, W, H,
       GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, big);
  pixel("big colour (10,10)", 10, 10);
  pixel("big colour (50,30)", 50, 30);
  depth("big depth (10,10)", 10, 10);
  depth("big depth (40,10)", 40, 10);
  depth("big depth (60,60)", 60, 60);
  stencil("big stencil (10,10)", 10, 10);
  stencil("big stencil (60,60)", 60, 60);

  /* The window scaled down into `small`: NEAREST, then LINEAR over the ramp. A scale of
   * 2:1 would put each NEAREST sample exactly between two rows, and Mesa's OSMesa window
   * is a y-flipped buffer, so such a tie falls to the other row than from an FBO (measured:
   * one row of depth); the scales here are odd over even, which never tie. */
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, small);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  blit("window into small, NEAREST", 0, 0, W - 1, 47, 0, 0, 32, 24, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  blit("window into small, LINEAR", 0, 48, W, H, 0, 24, 32, 32, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  blit("window depth into small", 0, 0, W - 1, H - 1, 0, 0, 32, 32, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, small);
  pixel("small (5,5)", 5, 5);
  pixel("small (20,20)", 20, 20);
  for (int x = 0; x < 32; x += 7) {
    char what[40];
    snprintf(what, sizeof what, "small ramp x=%d", x);
    pixel(what, x, 28);
  }
  depth("small depth (5,5)", 5, 5);
  depth("small depth (16,4)", 16, 4);

  /* Back to the window: `small` scaled up, flipped in x and in y, NEAREST and LINEAR, and
   * under the scissor test and the colour mask. */
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  blit("small flipped x into window", 0, 0, 32, 32, 32, 0, 0, 32, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  blit("small flipped y, scaled, LINEAR", 0, 0, 32, 32, 32, 64, 64, 32, GL_COLOR_BUFFER_BIT,
       GL_LINEAR);
  glEnable(GL_SCISSOR_TEST);
  glScissor(4, 36, 20, 20);
  blit("scissored blit", 0, 0, 32, 32, 0, 32, 32, 64, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  pixel("window (60,60) before the mask", 60, 60);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, small);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  blit("blit under colour mask", 0, 0, 8, 8, 56, 56, 64, 64, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  /* Mesa's library exports no EXT names: the program asks for it, as programs did. */
  PFNGLBLITFRAMEBUFFEREXTPROC blit_ext =
      (PFNGLBLITFRAMEBUFFEREXTPROC)OSMesaGetProcAddress("glBlitFramebufferEXT");
  printf("%-40s %d\n", "glBlitFramebufferEXT resolved", blit_ext != NULL);
  if (blit_ext) blit_ext(0, 0, 7, 7, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  err("glBlitFramebufferEXT");
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  pixel("window (40,10) flipped", 40, 10);
  pixel("window (10,40) scissored", 10, 40);
  pixel("window (2,40) outside scissor", 2, 40);
  pixel("window (60,60) colour mask", 60, 60);
  pixel("window (1,1) EXT blit", 1, 1);

  /* A blit in a display list runs when the list does. */
  GLuint list = glGenLists(1);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, big);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glNewList(list, GL_COMPILE);
  glBlitFramebuffer(0, 0, 8, 8, 24, 24, 40, 40, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glEndList();
  err("blit compiled");
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  pixel("window (30,30) after compiling", 30, 30);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, big);
  glCallList(list);
  err("list called");
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  pixel("window (30,30) after the list", 30, 30);

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glFinish();
  GLuint fbs[7] = {small, big, fb16, fb32f, fb24, fbf, broken};
  GLuint rbs[9] = {small_c, small_z, big_c, big_z, d16, d32f, d24, rgba16f, empty_rb};
  glDeleteFramebuffers(7, fbs);
  glDeleteRenderbuffers(9, rbs);
  err("deleted");
  if (argc > 1 && !write_ppm(argv[1], buffer, W, H)) return 3;
  OSMesaDestroyContext(ctx);
  return 0;
}
