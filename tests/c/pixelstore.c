/* glPixelStore through the C library: every unpack and pack parameter on every reader and
 * writer of client pixels. Six panels — a glDrawPixels of a sub-rectangle (ROW_LENGTH,
 * SKIP_ROWS, SKIP_PIXELS, ALIGNMENT 1), an unsigned-short image with SWAP_BYTES, glBitmap
 * glyphs read LSB first with bit skips, a polygon stipple read LSB first, a 2D texture
 * specified and sub-specified with skips and swapped bytes, a 1D texture with skipped
 * pixels — then one line per query: every parameter's glGet answer, the client attribute
 * stack, glReadPixels, glGetTexImage and glGetPolygonStipple written with the pack
 * parameters into sentinel-filled memory (printed byte by byte), and the errors.
 *
 * usage: pixelstore OUT.ppm */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl_resolve.h"

#define W 192
#define H 128

static void panel(int i) {
  glViewport((i % 3) * 64, (i / 3) * 64, 64, 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 64, 0, 64, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

static void report(const char *step) { printf("%-44s 0x%04x\n", step, (unsigned)glGetError()); }

static void dump(const char *name, const GLubyte *b, int n) {
  printf("%-24s", name);
  for (int i = 0; i < n; i++) printf("%s%02x", i % 16 == 0 && i ? "\n                        " : " ", b[i]);
  printf("\n");
}

static void defaults(void) {
  static const GLenum names[] = {GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS,   GL_UNPACK_SKIP_PIXELS,
                                 GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST,   GL_UNPACK_IMAGE_HEIGHT,
                                 GL_UNPACK_SKIP_IMAGES, GL_PACK_ROW_LENGTH,   GL_PACK_SKIP_ROWS,
                                 GL_PACK_SKIP_PIXELS,  GL_PACK_SWAP_BYTES,    GL_PACK_LSB_FIRST,
                                 GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_IMAGES};
  for (unsigned i = 0; i < sizeof names / sizeof names[0]; i++) glPixelStorei(names[i], 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
}

static void print_store(const char *when) {
  static const struct {
    const char *name;
    GLenum pname;
  } p[] = {
      {"UNPACK_SWAP_BYTES", GL_UNPACK_SWAP_BYTES},     {"UNPACK_LSB_FIRST", GL_UNPACK_LSB_FIRST},
      {"UNPACK_ROW_LENGTH", GL_UNPACK_ROW_LENGTH},     {"UNPACK_SKIP_ROWS", GL_UNPACK_SKIP_ROWS},
      {"UNPACK_SKIP_PIXELS", GL_UNPACK_SKIP_PIXELS},   {"UNPACK_ALIGNMENT", GL_UNPACK_ALIGNMENT},
      {"UNPACK_IMAGE_HEIGHT", GL_UNPACK_IMAGE_HEIGHT}, {"UNPACK_SKIP_IMAGES", GL_UNPACK_SKIP_IMAGES},
      {"PACK_SWAP_BYTES", GL_PACK_SWAP_BYTES},         {"PACK_LSB_FIRST", GL_PACK_LSB_FIRST},
      {"PACK_ROW_LENGTH", GL_PACK_ROW_LENGTH},         {"PACK_SKIP_ROWS", GL_PACK_SKIP_ROWS},
      {"PACK_SKIP_PIXELS", GL_PACK_SKIP_PIXELS},       {"PACK_ALIGNMENT", GL_PACK_ALIGNMENT},
      {"PACK_IMAGE_HEIGHT", GL_PACK_IMAGE_HEIGHT},     {"PACK_SKIP_IMAGES", GL_PACK_SKIP_IMAGES},
  };
  printf("%s:", when);
  for (unsigned i = 0; i < sizeof p / sizeof p[0]; i++) {
    GLint v = -7;
    GLboolean b = 7;
    glGetIntegerv(p[i].pname, &v);
    glGetBooleanv(p[i].pname, &b);
    printf(" %s=%d/%d", p[i].name, v, b);
  }
  printf("\n");
}

int main(int argc, char **argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s OUT.ppm\n", argv[0]);
    return 2;
  }
  static GLubyte buffer[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) return 1;
  resolve_gl();
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  print_store("defaults");

  /* A 23×30 RGB image; 17×20 of it drawn from column 3, row 2, rows tight (ALIGNMENT 1). */
  static GLubyte big[30][23][3];
  for (int y = 0; y < 30; y++)
    for (int x = 0; x < 23; x++) {
      big[y][x][0] = (GLubyte)(x * 11);
      big[y][x][1] = (GLubyte)(y * 8);
      big[y][x][2] = (GLubyte)(x == 3 || y == 2 ? 255 : 60);
    }
  panel(0);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 23);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(4, 4);
  glDrawPixels(17, 20, GL_RGB, GL_UNSIGNED_BYTE, big);
  /* The same with ALIGNMENT 8 and ROW_LENGTH 7 on a 7-wide RGB block: rows of 24 bytes. */
  static GLubyte padded[10][24];
  for (int y = 0; y < 10; y++)
    for (int x = 0; x < 24; x++) padded[y][x] = (GLubyte)(x < 21 ? (x % 3 == y % 3 ? 230 : 20) : 0);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glRasterPos2i(30, 40);
  glDrawPixels(7, 10, GL_RGB, GL_UNSIGNED_BYTE, padded);
  print_store("after panel 0");
  report("draw with row length and skips");
  defaults();

  /* Unsigned shorts in the other byte order: 16×16 RGBA. */
  panel(1);
  static GLushort shorts[16][16][4];
  for (int y = 0; y < 16; y++)
    for (int x = 0; x < 16; x++) {
      GLushort v[4] = {(GLushort)(x * 4096), (GLushort)(y * 4096), 0x8000, 0xFFFF};
      for (int c = 0; c < 4; c++) shorts[y][x][c] = (GLushort)((v[c] >> 8) | (v[c] << 8));
    }
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  glRasterPos2i(8, 8);
  glDrawPixels(16, 16, GL_RGBA, GL_UNSIGNED_SHORT, shorts);
  /* glPixelStoref rounds 0.4 to FALSE. The same bytes are drawn again from another
   * array: Mesa 22.3 keeps the image of a glDrawPixels from the same pointer and size
   * (st_DrawPixels' cache) and would draw it swapped, the new SWAP_BYTES unseen. */
  static GLushort shorts2[16][16][4];
  memcpy(shorts2, shorts, sizeof shorts);
  glPixelStoref(GL_UNPACK_SWAP_BYTES, 0.4f);
  glRasterPos2i(30, 30);
  glDrawPixels(16, 16, GL_RGBA, GL_UNSIGNED_SHORT, shorts2);
  report("draw swapped shorts");
  defaults();

  /* Bitmaps read least significant bit first, 3 bits skipped, rows of 4 bytes. */
  panel(2);
  static const GLubyte glyph[12][4] = {
      {0x18, 0x00, 0x00, 0}, {0x3c, 0x01, 0x80, 0}, {0x66, 0x03, 0xc0, 0}, {0xc3, 0x07, 0xe0, 0},
      {0xff, 0x0f, 0xf0, 0}, {0x81, 0x1f, 0xf8, 0}, {0x81, 0x3f, 0xfc, 0}, {0xc3, 0x7f, 0xfe, 0},
      {0x66, 0xff, 0xff, 0}, {0x3c, 0x0f, 0x0f, 0}, {0x18, 0x55, 0xaa, 0}, {0x00, 0xff, 0x00, 0}};
  glColor3f(1, 0.8f, 0.2f);
  glRasterPos2i(2, 2);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glBitmap(20, 12, 0, 0, 22, 0, &glyph[0][0]);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glBitmap(20, 12, 0, 0, -22, 14, &glyph[0][0]);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 5);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 32);
  glBitmap(19, 10, 0, 0, 22, 0, &glyph[0][0]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 24);
  glBitmap(19, 10, 0, 0, 0, 14, &glyph[0][0]);
  report("bitmaps LSB first, skipped");
  defaults();

  /* A polygon stipple read LSB first with rows of 5 bytes (ROW_LENGTH 40, ALIGNMENT 1). */
  panel(3);
  static GLubyte stipple[32][5];
  for (int y = 0; y < 32; y++)
    for (int x = 0; x < 5; x++) stipple[y][x] = (GLubyte)(x == 4 ? 0xff : (0x01 << (y % 8)) | 0x0f);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 40);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPolygonStipple(&stipple[0][0]);
  defaults();
  glEnable(GL_POLYGON_STIPPLE);
  glColor3f(0.3f, 0.9f, 0.9f);
  glRectf(4, 4, 60, 60);
  glDisable(GL_POLYGON_STIPPLE);
  GLubyte got[200];
  memset(got, 0xEE, sizeof got);
  glPixelStorei(GL_PACK_LSB_FIRST, GL_TRUE);
  glPixelStorei(GL_PACK_ROW_LENGTH, 48);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  glPixelStorei(GL_PACK_SKIP_ROWS, 1);
  glGetPolygonStipple(got);
  dump("stipple LSB first", got, 32);
  dump("stipple last rows", got + 170, 30);
  defaults();
  report("stipple LSB first");

  /* A 2D texture from a 9×9 RGBA image at (2, 1), 6×6 of it; then a sub-image of
   * swapped unsigned shorts (RGB, rows of 4 groups). */
  panel(4);
  static GLubyte texels[9][9][4];
  for (int y = 0; y < 9; y++)
    for (int x = 0; x < 9; x++) {
      texels[y][x][0] = (GLubyte)(x * 28);
      texels[y][x][1] = (GLubyte)(y * 28);
      texels[y][x][2] = (GLubyte)((x + y) % 2 ? 200 : 30);
      texels[y][x][3] = 255;
    }
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 9);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 6, 6, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  defaults();
  static GLushort sub[3][4][3];
  for (int y = 0; y < 3; y++)
    for (int x = 0; x < 4; x++)
      for (int c = 0; c < 3; c++) {
        GLushort v = (GLushort)(c == 2 ? 0xFFFF : (x * 20000 + y * 3000 + c * 7000));
        sub[y][x][c] = (GLushort)((v >> 8) | (v << 8));
      }
  /* Rows of 4 groups, 3 read. Not with SKIP_PIXELS: Mesa 22.3 then reads the last group
   * of each row as (0, 0, 0) when SWAP_BYTES is set (measured; GL 1.5 §3.6.4 reads it). */
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 2, 3, 3, GL_RGB, GL_UNSIGNED_SHORT, sub);
  defaults();
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0); glVertex2f(4, 4);
  glTexCoord2f(1, 0); glVertex2f(52, 4);
  glTexCoord2f(1, 1); glVertex2f(52, 52);
  glTexCoord2f(0, 1); glVertex2f(4, 52);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  memset(got, 0xEE, sizeof got);
  glPixelStorei(GL_PACK_ROW_LENGTH, 7);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
  glPixelStorei(GL_PACK_SKIP_ROWS, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);
  GLubyte whole[6 * 6 * 4 + 7 * 4 * 2 + 64];
  memset(whole, 0xEE, sizeof whole);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, whole);
  dump("tex image row 0", whole + 28, 28);
  dump("tex image row 2", whole + 3 * 28 + 4, 24);
  dump("tex image after", whole + 7 * 28, 8);
  GLushort wide[64];
  memset(wide, 0xEE, sizeof wide);
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_SHORT, wide);
  dump("tex image swapped", (const GLubyte *)wide, 48);
  defaults();
  report("tex image with skips and swaps");

  /* A 1D texture from 40 texels, 32 of them after 5 skipped (ROW_LENGTH ignored). */
  panel(5);
  static GLubyte line[40][3];
  for (int x = 0; x < 40; x++) {
    line[x][0] = (GLubyte)(x * 6);
    line[x][1] = (GLubyte)(x == 5 ? 255 : 0);
    line[x][2] = (GLubyte)(255 - x * 6);
  }
  GLuint tex1 = 0;
  glGenTextures(1, &tex1);
  glBindTexture(GL_TEXTURE_1D, tex1);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 5);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, line);
  defaults();
  glEnable(GL_TEXTURE_1D);
  glBegin(GL_QUADS);
  glTexCoord1f(0); glVertex2f(4, 4);
  glTexCoord1f(1); glVertex2f(60, 4);
  glTexCoord1f(1); glVertex2f(60, 60);
  glTexCoord1f(0); glVertex2f(4, 60);
  glEnd();
  glDisable(GL_TEXTURE_1D);
  report("1D texture with skipped pixels");

  /* glReadPixels of panel 0's exact pixels with the pack parameters. */
  GLubyte read[160];
  memset(read, 0xEE, sizeof read);
  glPixelStorei(GL_PACK_ROW_LENGTH, 5);
  glPixelStorei(GL_PACK_SKIP_ROWS, 1);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);
  glReadPixels(5, 6, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, read);
  dump("read RGB skips", read, 64);
  GLushort reads[32];
  memset(reads, 0xEE, sizeof reads);
  defaults();
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 2);
  glReadPixels(8, 8, 2, 1, GL_RGB, GL_UNSIGNED_SHORT, reads);
  dump("read shorts swapped", (const GLubyte *)reads, 24);
  defaults();
  report("read with pack parameters");

  /* Pixel maps (GL 1.5 §3.6.3): an inverting R map, a 3-entry G map, B and A maps from
   * unsigned shorts and ints, applied with MAP_COLOR to a glDrawPixels over panel 5 and
   * to a glCopyPixels of it; the sizes, the stored values and the errors. */
  panel(5);
  GLfloat inv[5] = {1.0f, 0.75f, 0.5f, 0.25f, 0.0f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 5, inv);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 3, (const GLfloat[]){0.2f, 1.5f, -1.0f});
  glPixelMapusv(GL_PIXEL_MAP_B_TO_B, 2, (const GLushort[]){65535, 16384});
  glPixelMapuiv(GL_PIXEL_MAP_A_TO_A, 1, (const GLuint[]){4294967295u});
  glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 4, (const GLfloat[]){2.5f, 1.4f, 300.0f, -2.0f});
  glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 2, (const GLuint[]){7, 9});
  /* Drawn with B_TO_B as a 256-entry identity: with the 2-entry map above, Mesa 22.3
   * draws blue 30 as 17 and 220 as 221 and glCopyPixels leaves blue as it was (measured),
   * where GL 1.5 §3.6.5 looks up entry round(b·(size − 1)). */
  GLfloat ident[256];
  for (int i = 0; i < 256; i++) ident[i] = (GLfloat)i / 255.0f;
  GLushort bmap[2] = {0, 0};
  glGetPixelMapusv(GL_PIXEL_MAP_B_TO_B, bmap);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 256, ident);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  static GLubyte ramp[8][16][3];
  for (int y = 0; y < 8; y++)
    for (int x = 0; x < 16; x++) {
      ramp[y][x][0] = (GLubyte)(x * 17);
      ramp[y][x][1] = (GLubyte)(y * 36);
      ramp[y][x][2] = (GLubyte)(x < 8 ? 30 : 220);
    }
  glRasterPos2i(40, 50);
  glDrawPixels(16, 8, GL_RGB, GL_UNSIGNED_BYTE, ramp);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  glRasterPos2i(40, 40);
  glDrawPixels(16, 8, GL_RGB, GL_UNSIGNED_BYTE, ramp);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glRasterPos2i(40, 20);
  glCopyPixels(128 + 40, 64 + 40, 16, 8, GL_COLOR);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  glPixelMapusv(GL_PIXEL_MAP_B_TO_B, 2, bmap);
  /* Red and green of the mapped rows, drawn and copied, are printed (blue differs on
   * Mesa, above); the rectangles are then cleared, out of the image comparison. */
  for (int y = 84; y <= 118; y += 34) {
    GLubyte row[16][3];
    glReadPixels(168, y, 16, 1, GL_RGB, GL_UNSIGNED_BYTE, row);
    printf("mapped row %d R/G:", y);
    for (int x = 0; x < 16; x += 3) printf(" %u/%u", row[x][0], row[x][1]);
    printf("\n");
  }
  glEnable(GL_SCISSOR_TEST);
  glScissor(168, 80, 16, 44);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  report("pixel maps drawn and copied");
  {
    static const struct {
      const char *name;
      GLenum map, size;
    } m[] = {{"I_TO_I", GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_I_TO_I_SIZE},
             {"S_TO_S", GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_S_TO_S_SIZE},
             {"I_TO_R", GL_PIXEL_MAP_I_TO_R, GL_PIXEL_MAP_I_TO_R_SIZE},
             {"I_TO_A", GL_PIXEL_MAP_I_TO_A, GL_PIXEL_MAP_I_TO_A_SIZE},
             {"R_TO_R", GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_R_TO_R_SIZE},
             {"G_TO_G", GL_PIXEL_MAP_G_TO_G, GL_PIXEL_MAP_G_TO_G_SIZE},
             {"B_TO_B", GL_PIXEL_MAP_B_TO_B, GL_PIXEL_MAP_B_TO_B_SIZE},
             {"A_TO_A", GL_PIXEL_MAP_A_TO_A, GL_PIXEL_MAP_A_TO_A_SIZE}};
    for (unsigned i = 0; i < sizeof m / sizeof m[0]; i++) {
      GLint n = -1;
      glGetIntegerv(m[i].size, &n);
      GLfloat f[8] = {0};
      GLuint u[8] = {0};
      GLushort us[8] = {0};
      glGetPixelMapfv(m[i].map, f);
      glGetPixelMapuiv(m[i].map, u);
      glGetPixelMapusv(m[i].map, us);
      /* GLuint of an index map as Mesa 22.3 gives it (and the layer follows): I_TO_I as
       * FLOAT_TO_UINT of the integer (7 → 2^32 − 7, a wrapped overflow), S_TO_S as the
       * float's bits. */
      printf("%s size %d:", m[i].name, n);
      for (int k = 0; k < n && k < 8; k++) printf(" %.4f/%u/%u", f[k], u[k], us[k]);
      printf("\n");
    }
    GLint max = 0;
    glGetIntegerv(GL_MAX_PIXEL_MAP_TABLE, &max);
    printf("GL_MAX_PIXEL_MAP_TABLE %d\n", max);
  }
  report("pixel map queries");
  glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 3, inv);
  report("S_TO_S of 3 entries");
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 6, inv);
  report("I_TO_G of 6 entries");
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, inv);
  report("R_TO_R of 0 entries");
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 257, inv);
  report("R_TO_R of 257 entries");
  glPixelMapfv(GL_TEXTURE_2D, 2, inv);
  report("a bad map");
  glGetPixelMapfv(GL_TEXTURE_2D, inv);
  report("glGetPixelMapfv of a bad map");
  glPushAttrib(GL_PIXEL_MODE_BIT);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 1, (const GLfloat[]){0.5f});
  glPopAttrib();
  {
    GLint n = 0;
    glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, &n);
    printf("R_TO_R size after glPopAttrib: %d\n", n);
  }
  report("pixel maps on the attribute stack");

  /* The client attribute stack keeps every parameter. */
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 11);
  glPixelStorei(GL_PACK_SKIP_IMAGES, 3);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 6);
  glPixelStorei(GL_PACK_LSB_FIRST, 1);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  defaults();
  glPixelStorei(GL_UNPACK_SWAP_BYTES, 1);
  print_store("pushed, changed");
  glPopClientAttrib();
  print_store("popped");
  defaults();
  report("client attribute stack");

  /* Errors. */
  glPixelStorei(GL_UNPACK_ROW_LENGTH, -1);
  report("negative UNPACK_ROW_LENGTH");
  glPixelStorei(GL_PACK_SKIP_PIXELS, -3);
  report("negative PACK_SKIP_PIXELS");
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, -1);
  report("negative UNPACK_SKIP_IMAGES");
  glPixelStorei(GL_PACK_IMAGE_HEIGHT, -1);
  report("negative PACK_IMAGE_HEIGHT");
  glPixelStorei(GL_UNPACK_ALIGNMENT, 3);
  report("UNPACK_ALIGNMENT 3");
  glPixelStorei(GL_PACK_ALIGNMENT, 16);
  report("PACK_ALIGNMENT 16");
  glPixelStorei(GL_TEXTURE_2D, 1);
  report("a bad pname");
  glPixelStoref(GL_UNPACK_SKIP_ROWS, 2.6f);
  glPixelStoref(GL_PACK_ALIGNMENT, 1.6f);
  glPixelStoref(GL_PACK_SWAP_BYTES, 0.6f);
  print_store("glPixelStoref rounds");
  report("glPixelStoref");

  glFinish();
  if (!write_ppm(argv[1], buffer, W, H)) return 1;
  OSMesaDestroyContext(ctx);
  return 0;
}
