/* GL 1.0's signed pixel types, GL 1.2's packed types and its BGR and BGRA formats, on the
 * way in and on the way out: which format and type pairs each call refuses, what
 * glTexImage2D, glTexSubImage2D and glDrawPixels store from each (read back as RGBA bytes,
 * and drawn into panels), and what glReadPixels and glGetTexImage give in each (printed
 * as the bytes of the client's memory). Run on Mesa's OSMesa and on fixedfunc's library,
 * the printed lines must be the same and the images match.
 *
 * usage: pixel_types [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"
#define W 64
#define H 32
static GLubyte *buf;
static int panels;

static const struct { GLenum type; const char *name; int bytes; } packed[] = {
    {GL_UNSIGNED_BYTE_3_3_2, "3_3_2", 1},
    {GL_UNSIGNED_BYTE_2_3_3_REV, "2_3_3_REV", 1},
    {GL_UNSIGNED_SHORT_5_6_5, "5_6_5", 2},
    {GL_UNSIGNED_SHORT_5_6_5_REV, "5_6_5_REV", 2},
    {GL_UNSIGNED_SHORT_4_4_4_4, "4_4_4_4", 2},
    {GL_UNSIGNED_SHORT_4_4_4_4_REV, "4_4_4_4_REV", 2},
    {GL_UNSIGNED_SHORT_5_5_5_1, "5_5_5_1", 2},
    {GL_UNSIGNED_SHORT_1_5_5_5_REV, "1_5_5_5_REV", 2},
    {GL_UNSIGNED_INT_8_8_8_8, "8_8_8_8", 4},
    {GL_UNSIGNED_INT_8_8_8_8_REV, "8_8_8_8_REV", 4},
    {GL_UNSIGNED_INT_10_10_10_2, "10_10_10_2", 4},
    {GL_UNSIGNED_INT_2_10_10_10_REV, "2_10_10_10_REV", 4},
};
#define NPACKED (int)(sizeof packed / sizeof packed[0])

static const struct { GLenum format; const char *name; } formats[] = {
    {GL_RGB, "RGB"}, {GL_BGR, "BGR"}, {GL_RGBA, "RGBA"}, {GL_BGRA, "BGRA"},
    {GL_LUMINANCE, "LUMINANCE"}, {GL_DEPTH_COMPONENT, "DEPTH"},
};
#define NFORMATS (int)(sizeof formats / sizeof formats[0])

/* The bound texture's 2×2 level 0 as RGBA bytes, and a panel drawn with it (REPLACE). */
static void show(const char *what) {
  GLubyte t[4 * 4] = {0};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  printf("%-26s", what);
  for (int i = 0; i < 16; i++) printf(" %d", t[i]);
  printf(" err %x\n", glGetError());
  glViewport((panels % 8) * 8, 8 + (panels / 8) * 8, 8, 8);
  panels++;
  glEnable(GL_TEXTURE_2D);
  glRectf(-1, -1, 1, 1);
  glDisable(GL_TEXTURE_2D);
  glViewport(0, 0, W, H);
}

static void hex(const char *what, const GLubyte *b, int n) {
  printf("%-26s", what);
  for (int i = 0; i < n; i++) printf(" %02x", b[i]);
  printf(" err %x\n", glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "pixel_types.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  replace_texture_panels();

  /* Which packed types go with which formats: the error of each glTexImage2D, glDrawPixels
   * and glReadPixels, one letter each (0 none, E enum, V value, O operation). */
  GLubyte scratch[64] = {0};
  for (int p = 0; p < NPACKED; p++) {
    char line[3 * NFORMATS + 1];
    for (int f = 0; f < NFORMATS; f++) {
      GLenum e[3];
      GLenum internal = formats[f].format == GL_DEPTH_COMPONENT ? GL_DEPTH_COMPONENT : GL_RGBA;
      glTexImage2D(GL_TEXTURE_2D, 0, internal, 1, 1, 0, formats[f].format, packed[p].type,
                   scratch);
      e[0] = glGetError();
      glRasterPos2f(0.9f, 0.9f);
      glDrawPixels(1, 1, formats[f].format, packed[p].type, scratch);
      e[1] = glGetError();
      glReadPixels(0, 0, 1, 1, formats[f].format, packed[p].type, scratch);
      e[2] = glGetError();
      for (int k = 0; k < 3; k++)
        line[3 * f + k] = e[k] == 0 ? '0' : e[k] == GL_INVALID_ENUM ? 'E'
                        : e[k] == GL_INVALID_VALUE ? 'V' : e[k] == GL_INVALID_OPERATION ? 'O' : '?';
    }
    line[3 * NFORMATS] = 0;
    printf("%-26s %s\n", packed[p].name, line);
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_BGRA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, scratch);
  err("internal format BGRA");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_BGRA, GL_BITMAP, scratch);
  err("BGRA in BITMAP");
  glClear(GL_COLOR_BUFFER_BIT);

  /* In: BGR(A) and the signed types into RGBA textures. */
  GLubyte bgra[16] = {255, 128, 0, 255, 10, 20, 30, 40, 0, 0, 255, 128, 17, 34, 51, 68};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_BGRA, GL_UNSIGNED_BYTE, bgra);
  show("BGRA ubyte");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_BGR, GL_UNSIGNED_BYTE, bgra);
  show("BGR ubyte");
  GLushort bgra16[16] = {65535, 32768, 0, 65535, 1000, 2000, 3000, 4000,
                         0, 0, 65535, 32896, 4369, 8738, 13107, 17476};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_BGRA, GL_UNSIGNED_SHORT, bgra16);
  show("BGRA ushort");
  GLfloat bgraf[16] = {1, 0.5f, 0, 1, 0.1f, 0.2f, 0.3f, 0.4f, 0, 0, 1, 0.5f, 0.7f, 0.8f, 0.9f, 1};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_BGRA, GL_FLOAT, bgraf);
  show("BGRA float");
  GLbyte sb[16] = {-128, -127, -1, 0, 1, 63, 64, 127, 100, -100, 32, 96, 0, 127, 127, 127};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_BYTE, sb);
  show("RGBA byte");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_BGRA, GL_BYTE, sb);
  show("BGRA byte");
  GLshort ss[16] = {-32768, -1, 0, 1, 16383, 16384, 32767, 12345,
                    -12345, 8191, 24575, 100, 32767, 0, 16000, 30000};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_SHORT, ss);
  show("RGBA short");
  GLint si[16] = {INT_MIN, -1, 0, 1, 1 << 30, INT_MAX, 123456789, 1 << 29,
                  -(1 << 30), 1 << 28, 2000000000, 1000000000, INT_MAX, 0, 1 << 20, 1 << 24};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_INT, si);
  show("RGBA int");
  GLbyte lb[4] = {-5, 50, 100, 127};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 2, 2, 0, GL_LUMINANCE, GL_BYTE, lb);
  show("LUMINANCE byte");

  /* In: every packed type, four groups of varied fields, as texture and sub-image. */
  for (int p = 0; p < NPACKED; p++) {
    GLubyte data[16];
    for (int i = 0; i < 16; i++) data[i] = (GLubyte)(37 * i + 11 * p + 5);
    GLenum format = packed[p].bytes == 1 || p == 2 || p == 3 ? GL_RGB : GL_RGBA;
    char name[40];
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, format, packed[p].type, data);
    snprintf(name, sizeof name, "in %s", packed[p].name);
    show(name);
    if (format == GL_RGBA) {
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_BGRA, packed[p].type, data);
      snprintf(name, sizeof name, "in BGRA %s", packed[p].name);
      show(name);
    }
  }
  GLushort sub = 0xf81f;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_BGR, GL_UNSIGNED_BYTE, bgra);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &sub);
  show("sub-image 5_6_5");

  /* In: glDrawPixels of BGRA, a signed and a packed type, read back as bytes. */
  glRasterPos2f(-1, -1);
  glDrawPixels(2, 2, GL_BGRA, GL_UNSIGNED_BYTE, bgra);
  glRasterPos2f(-0.5f, -1);
  glDrawPixels(2, 2, GL_RGBA, GL_BYTE, sb);
  glRasterPos2f(0, -1);
  GLushort p565[4] = {0xf800, 0x07e0, 0x001f, 0x8410};
  glDrawPixels(2, 2, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, p565);
  glRasterPos2f(0.5f, -1);
  GLuint p1010[4] = {0xffc00003u, 0x000ffc01u, 0x00003ff2u, 0x80200802u};
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, p1010);
  {
    GLubyte r[4 * 8];
    glReadPixels(0, 0, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE, r);
    hex("drawn row 0 (0..7)", r, 32);
    glReadPixels(16, 0, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE, r);
    hex("drawn row 0 (16..23)", r, 32);
    glReadPixels(32, 0, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE, r);
    hex("drawn row 0 (32..39)", r, 32);
    glReadPixels(48, 0, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE, r);
    hex("drawn row 0 (48..55)", r, 32);
  }

  /* Out: a row of known colours read in every type and from a texture of them. */
  GLubyte row[4 * 4] = {255, 0, 128, 255, 1, 2, 3, 4, 127, 128, 129, 200, 16, 66, 140, 250};
  glRasterPos2f(-1, 0);
  glDrawPixels(4, 1, GL_RGBA, GL_UNSIGNED_BYTE, row);
  int y0 = H / 2;
  GLubyte r[4 * 16];
  memset(r, 0xee, sizeof r);
  glReadPixels(0, y0, 4, 1, GL_BGRA, GL_UNSIGNED_BYTE, r);
  hex("read BGRA ubyte", r, 16);
  glReadPixels(0, y0, 4, 1, GL_BGR, GL_UNSIGNED_BYTE, r);
  hex("read BGR ubyte", r, 12);
  glReadPixels(0, y0, 2, 1, GL_BGRA, GL_UNSIGNED_SHORT, r);
  hex("read BGRA ushort", r, 16);
  glReadPixels(0, y0, 4, 1, GL_RGBA, GL_BYTE, r);
  hex("read RGBA byte", r, 16);
  glReadPixels(0, y0, 2, 1, GL_BGRA, GL_SHORT, r);
  hex("read BGRA short", r, 16);
  glReadPixels(0, y0, 1, 1, GL_RGBA, GL_INT, r);
  hex("read RGBA int", r, 16);
  glReadPixels(0, y0, 4, 1, GL_LUMINANCE, GL_BYTE, r);
  hex("read LUMINANCE byte", r, 4);
  for (int p = 0; p < NPACKED; p++) {
    GLenum format = packed[p].bytes == 1 || p == 2 || p == 3 ? GL_RGB : GL_RGBA;
    char name[40];
    memset(r, 0xee, sizeof r);
    glReadPixels(0, y0, 4, 1, format, packed[p].type, r);
    snprintf(name, sizeof name, "read %s", packed[p].name);
    hex(name, r, 4 * packed[p].bytes);
    if (format == GL_RGBA) {
      glReadPixels(0, y0, 4, 1, GL_BGRA, packed[p].type, r);
      snprintf(name, sizeof name, "read BGRA %s", packed[p].name);
      hex(name, r, 4 * packed[p].bytes);
    }
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, row);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_BGRA, GL_UNSIGNED_BYTE, r);
  hex("texture BGRA ubyte", r, 16);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_BYTE, r);
  hex("texture RGBA byte", r, 16);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, r);
  hex("texture 5_6_5", r, 8);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, r);
  hex("texture BGRA 1_5_5_5_REV", r, 8);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, r);
  hex("texture 2_10_10_10_REV", r, 16);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_SHORT_5_6_5, r);
  err("texture LUMINANCE 5_6_5");

  /* Non-finite floats in BGRA: into a texture, drawn, read back as bytes and as BYTE. */
  GLfloat odd[8] = {NAN, INFINITY, -INFINITY, 0.5f, -0.0f, 2.0f, NAN, -NAN};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_BGRA, GL_FLOAT, odd);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, r);
  hex("non-finite BGRA texture", r, 8);
  glRasterPos2f(0.5f, 0.5f);
  glDrawPixels(2, 1, GL_BGRA, GL_FLOAT, odd);
  glReadPixels(W * 3 / 4, H * 3 / 4, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, r);
  hex("non-finite BGRA drawn", r, 8);
  glReadPixels(W * 3 / 4, H * 3 / 4, 2, 1, GL_BGRA, GL_BYTE, r);
  hex("non-finite read as BYTE", r, 8);

  /* LUMINANCE and LUMINANCE_ALPHA as INT and UNSIGNED_INT: Mesa packs them through floats
   * (x times 2^31 or 2^32 as a float), so a full luminance overflows (INT_MIN; 0). */
  glColor4f(0.5f, 0.4f, 0.3f, 177 / 255.0f);
  glDisable(GL_TEXTURE_2D);
  glRectf(-1, -1, 1, 1);
  static const GLenum luminance_formats[] = {GL_LUMINANCE, GL_LUMINANCE_ALPHA};
  static const GLenum int_types[] = {GL_INT, GL_UNSIGNED_INT};
  for (int f = 0; f < 2; f++)
    for (int t = 0; t < 2; t++) {
      GLubyte words[8];
      memset(words, 0xab, sizeof words);
      glReadPixels(1, 1, 1, 1, luminance_formats[f], int_types[t], words);
      hex(f ? (t ? "LA as UNSIGNED_INT" : "LA as INT") : (t ? "L as UNSIGNED_INT" : "L as INT"),
          words, 8);
    }
  /* glGetTexImage packs luminance as UNSIGNED_INT through floats too, as INT exactly. */
  static const GLubyte la[4] = {10, 177, 255, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 2, 1, 0, GL_LUMINANCE_ALPHA,
               GL_UNSIGNED_BYTE, la);
  for (int t = 0; t < 2; t++) {
    GLubyte words[16];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, int_types[t], words);
    hex(t ? "LA texture as UNSIGNED_INT" : "LA texture as INT", words, 16);
  }

  glViewport(0, 0, W, H);
  return finish(out, ctx, buf, W, H);
}
