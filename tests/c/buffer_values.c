/* The values glClear, glDrawPixels and glReadPixels leave in and give from the depth,
 * stencil and colour buffers, printed one per line: clears under glDepthMask and
 * glStencilMask with the depth and stencil tests off and on (GL 1.5 §4.2.3: the masks
 * apply either way), stencil images drawn over a cleared stencil buffer (each value
 * replaces the stored one under the write mask), stencil indices read through
 * INDEX_SHIFT, INDEX_OFFSET and MAP_STENCIL (§4.3.2), depths read in the signed and
 * unsigned types, alpha read alone in the wider types, colours drawn through MAP_COLOR's
 * maps and depths drawn from unsigned bytes, and the errors of reading colour indices.
 * Run on Mesa's OSMesa and on fixedfunc's library, the printed lines must be the same and
 * the images match.
 *
 * usage: buffer_values [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 32
#define H 32

/* The stencil and depth values at (x, y). */
static void stencil_depth(const char *what, int x, int y) {
  GLubyte s = 0;
  GLfloat d = -1;
  glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
  glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
  printf("%-40s stencil 0x%02x depth %g err 0x%x\n", what, s, d, glGetError());
}

/* Clears depth to 0.25 and stencil to 0x34 with the masks open, then to 1.0 and 0xa5
 * under depth mask FALSE and stencil mask 0x0f, the tests on or off. */
static void masked_clear(const char *what, int tests) {
  glDepthMask(GL_TRUE);
  glStencilMask(0xff);
  glClearDepth(0.25);
  glClearStencil(0x34);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glDepthMask(GL_FALSE);
  glStencilMask(0x0f);
  if (tests) {
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
  }
  glClearDepth(1.0);
  glClearStencil(0xa5);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  stencil_depth(what, 5, 5);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glDepthMask(GL_TRUE);
  glStencilMask(0xff);
}

/* Four stencil values drawn at row y over a stencil buffer of 7, then read. */
static void draw_stencil(const char *what, int y, GLenum type, const void *data) {
  glClearStencil(7);
  glClear(GL_STENCIL_BUFFER_BIT);
  glRasterPos2i(0, y);
  glDrawPixels(4, 1, GL_STENCIL_INDEX, type, data);
  GLubyte s[4] = {0};
  glReadPixels(0, y, 4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
  printf("%-40s %d %d %d %d err 0x%x\n", what, s[0], s[1], s[2], s[3], glGetError());
}

/* The stencil value at (0, 0) read as unsigned and signed bytes, unsigned shorts and
 * floats. */
static void read_stencil(const char *what) {
  GLubyte ub = 0;
  GLbyte b = 0;
  GLushort us = 0;
  GLfloat f = -1;
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &ub);
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_BYTE, &b);
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_SHORT, &us);
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_FLOAT, &f);
  printf("%-40s %d %d %d %g err 0x%x\n", what, ub, b, us, f, glGetError());
}

/* The depth at (0, 0) read in every integer type. */
static void read_depth(const char *what) {
  GLbyte b = 0;
  GLshort s = 0;
  GLint i = 0;
  GLubyte ub = 0;
  GLushort us = 0;
  GLuint ui = 0;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_BYTE, &b);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_SHORT, &s);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_INT, &i);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, &ub);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, &us);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &ui);
  printf("%-40s %d %d %d %u %u %u err 0x%x\n", what, b, s, i, ub, us, ui, glGetError());
}

/* The alpha at (0, 0) read alone in the unsigned types and as a float. */
static void read_alpha(const char *what) {
  GLubyte ub = 0;
  GLushort us = 0;
  GLuint ui = 0;
  GLfloat f = -1;
  glReadPixels(0, 0, 1, 1, GL_ALPHA, GL_UNSIGNED_BYTE, &ub);
  glReadPixels(0, 0, 1, 1, GL_ALPHA, GL_UNSIGNED_SHORT, &us);
  glReadPixels(0, 0, 1, 1, GL_ALPHA, GL_UNSIGNED_INT, &ui);
  glReadPixels(0, 0, 1, 1, GL_ALPHA, GL_FLOAT, &f);
  printf("%-40s %u 0x%04x 0x%08x %.9g err 0x%x\n", what, ub, us, ui, f, glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "buffer_values.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);

  /* glClear under the write masks. */
  masked_clear("masked clear, tests off", 0);
  masked_clear("masked clear, tests on", 1);

  /* Stencil images replace the stored values. */
  GLubyte ub[4] = {0, 37, 200, 255};
  GLfloat fl[4] = {0, 37, 200, 255};
  GLushort us[4] = {0, 37, 200, 0x1ff};
  draw_stencil("draw stencil ubyte", 0, GL_UNSIGNED_BYTE, ub);
  draw_stencil("draw stencil float", 1, GL_FLOAT, fl);
  draw_stencil("draw stencil ushort", 2, GL_UNSIGNED_SHORT, us);
  glStencilMask(0xf0);
  draw_stencil("draw stencil ubyte, mask 0xf0", 3, GL_UNSIGNED_BYTE, ub);
  glStencilMask(0xff);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NEVER, 0, 0);
  draw_stencil("draw stencil ubyte, test NEVER", 4, GL_UNSIGNED_BYTE, ub);
  glDisable(GL_STENCIL_TEST);

  /* Stencil indices read through the index arithmetic and MAP_STENCIL. */
  glClearStencil(100);
  glClear(GL_STENCIL_BUFFER_BIT);
  read_stencil("read stencil");
  glPixelTransferi(GL_INDEX_SHIFT, -1);
  read_stencil("read stencil, shift -1");
  glPixelTransferi(GL_INDEX_SHIFT, 2);
  read_stencil("read stencil, shift 2");
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 7);
  read_stencil("read stencil, offset 7");
  glPixelTransferi(GL_INDEX_OFFSET, -101);
  read_stencil("read stencil, offset -101");
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  GLuint map[2] = {9, 200};
  glPixelMapuiv(GL_PIXEL_MAP_S_TO_S, 2, map);
  glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
  read_stencil("read stencil, mapped");
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  read_stencil("read stencil, offset 1 then mapped");
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);

  /* Depths read in the signed and unsigned types. */
  static const double depths[] = {0, 0.25, 0.5, 0.75, 1, 0.123456};
  for (unsigned k = 0; k < sizeof depths / sizeof depths[0]; k++) {
    char line[48];
    snprintf(line, sizeof line, "read depth %g", depths[k]);
    glClearDepth(depths[k]);
    glClear(GL_DEPTH_BUFFER_BIT);
    read_depth(line);
  }

  /* Alpha read alone. */
  static const int alphas[] = {0, 1, 128, 231, 255};
  for (unsigned k = 0; k < sizeof alphas / sizeof alphas[0]; k++) {
    char line[48];
    snprintf(line, sizeof line, "read alpha %d/255", alphas[k]);
    glClearColor(0.5f, 0.25f, 1, alphas[k] / 255.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    read_alpha(line);
  }
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);

  /* MAP_COLOR on glDrawPixels: red through a 4-entry map, green through a 3-entry one
   * (blue and alpha masked off). */
  GLubyte ramp[32 * 4];
  for (int i = 0; i < 32; i++) {
    ramp[4 * i] = (GLubyte)(i * 255 / 31);
    ramp[4 * i + 1] = (GLubyte)(255 - i * 8);
    ramp[4 * i + 2] = 100;
    ramp[4 * i + 3] = 50;
  }
  GLfloat rmap[4] = {0, 0.2f, 0.9f, 1};
  GLfloat gmap[3] = {1, 0.5f, 0};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, rmap);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 3, gmap);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_FALSE, GL_FALSE);
  glRasterPos2i(0, 8);
  glDrawPixels(32, 1, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  GLubyte mapped[32 * 4];
  glReadPixels(0, 8, 32, 1, GL_RGBA, GL_UNSIGNED_BYTE, mapped);
  for (int i = 0; i < 32; i += 4) {
    char line[48];
    snprintf(line, sizeof line, "draw mapped, red %d green %d", ramp[4 * i], ramp[4 * i + 1]);
    printf("%-40s %d %d | %d %d | %d %d | %d %d\n", line, mapped[4 * i], mapped[4 * i + 1],
           mapped[4 * i + 4], mapped[4 * i + 5], mapped[4 * i + 8], mapped[4 * i + 9],
           mapped[4 * i + 12], mapped[4 * i + 13]);
  }

  /* Depths drawn from unsigned bytes (depth test ALWAYS, so they are written). */
  GLubyte zb[8] = {0, 1, 96, 97, 127, 128, 201, 255};
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glRasterPos2i(0, 12);
  glDrawPixels(8, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, zb);
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  GLuint zr[8] = {0};
  glReadPixels(0, 12, 8, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zr);
  for (int i = 0; i < 8; i++) {
    char line[48];
    snprintf(line, sizeof line, "draw depth ubyte %d", zb[i]);
    printf("%-40s 0x%08x\n", line, zr[i]);
  }

  /* Colour indices read from an RGBA framebuffer. */
  GLubyte ci[4] = {0};
  glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ci);
  err("read COLOR_INDEX");
  glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, GL_FLOAT, ci);
  err("read COLOR_INDEX as FLOAT");
  glReadPixels(0, 0, -1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ci);
  err("read COLOR_INDEX, negative width");
  glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, GL_RGBA, ci);
  err("read COLOR_INDEX, type RGBA");

  return finish(out, ctx, buf, W, H);
}
