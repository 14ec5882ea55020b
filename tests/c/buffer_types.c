/* The caller's buffer in every type Mesa's OSMesa takes for RGBA-family formats:
 * GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT (16-bit components) and GL_FLOAT (32-bit float
 * components), in OSMESA_RGBA, OSMESA_BGRA and OSMESA_ARGB, each rendered at its own
 * precision: a clear, a flat triangle and a smooth one, one pixel of each region printed
 * with RED_BITS. Mesa orders only byte components by the format: a GL_UNSIGNED_SHORT or
 * GL_FLOAT buffer holds RGBA whatever the format. A clear colour outside [0, 1] clears a
 * float buffer to itself. Run on Mesa's OSMesa and on fixedfunc's library, the printed
 * lines must be the same.
 *
 * usage: buffer_types */
#include <GL/osmesa.h>
#include <stdio.h>
#include <string.h>

#define W 8
#define H 8

static GLfloat fbuf[W * H * 4];
static GLushort sbuf[W * H * 4];
static GLubyte bbuf[W * H * 4];

static void draw(void) {
  glClearColor(0.3f, 0.6f, 1.0f / 3, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT);
  /* A flat triangle over the lower-left half, a smooth one in the top row. */
  glShadeModel(GL_FLAT);
  glColor4f(0.1f, 0.2f, 0.7f, 1);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(-1, 0.5f);
  glEnd();
  glShadeModel(GL_SMOOTH);
  glBegin(GL_TRIANGLES);
  glColor4f(1, 0, 0, 1);
  glVertex2f(-1, 0.75f);
  glColor4f(0, 1, 0, 1);
  glVertex2f(1, 0.75f);
  glColor4f(0, 0, 1, 0);
  glVertex2f(0, 1);
  glEnd();
  glFinish();
}

/* Pixel (x, y) of the buffer (row 0 is the bottom one) as its components. */
static void show(const char *what, GLenum type, int components, int x, int y) {
  int i = (y * W + x) * components;
  printf("%-24s", what);
  for (int k = 0; k < components; k++) {
    if (type == GL_FLOAT) printf(" %.4f", fbuf[i + k]);
    else if (type == GL_UNSIGNED_SHORT) printf(" %u", sbuf[i + k]);
    else printf(" %u", bbuf[i + k]);
  }
  printf("\n");
}

int main(void) {
  static const struct { GLenum format; const char *name; int components; } formats[] = {
      {OSMESA_RGBA, "RGBA", 4}, {OSMESA_BGRA, "BGRA", 4}, {OSMESA_ARGB, "ARGB", 4}};
  static const struct { GLenum type; const char *name; void *buffer; } types[] = {
      {GL_UNSIGNED_BYTE, "ubyte", bbuf}, {GL_UNSIGNED_SHORT, "ushort", sbuf},
      {GL_FLOAT, "float", fbuf}};
  for (int f = 0; f < 3; f++)
    for (int t = 0; t < 3; t++) {
      OSMesaContext ctx = OSMesaCreateContextExt(formats[f].format, 24, 8, 0, NULL);
      if (!ctx) return 1;
      GLboolean ok = OSMesaMakeCurrent(ctx, types[t].buffer, types[t].type, W, H);
      printf("%s %s: make current %d\n", formats[f].name, types[t].name, ok);
      if (!ok) {
        OSMesaDestroyContext(ctx);
        continue;
      }
      GLint bits = 0;
      glGetIntegerv(GL_RED_BITS, &bits);
      printf("%-24s %d\n", "red bits", bits);
      draw();
      show("flat", types[t].type, formats[f].components, 1, 1);
      show("clear", types[t].type, formats[f].components, W - 1, 3);
      show("smooth", types[t].type, formats[f].components, 3, 7);
      /* A clear colour outside [0, 1]: kept as given, clamped by a fixed-point buffer
       * only, answered clamped. */
      glClearColor(2.0f, -1.0f, 0.5f, 1.5f);
      glClear(GL_COLOR_BUFFER_BIT);
      glFinish();
      show("clear outside [0, 1]", types[t].type, formats[f].components, 0, 0);
      GLfloat v[4];
      glGetFloatv(GL_COLOR_CLEAR_VALUE, v);
      printf("%-24s %.4f %.4f %.4f %.4f\n", "clear value", v[0], v[1], v[2], v[3]);
      OSMesaDestroyContext(ctx);
    }
  /* Buffers without alpha: OSMESA_RGB of bytes and floats has ALPHA_BITS 0, and blending
   * reads a destination alpha of 1 (the clear's alpha 0.5 is not kept). */
  static const struct { GLenum type; const char *name; void *buffer; } rgb[] = {
      {GL_UNSIGNED_BYTE, "RGB ubyte", bbuf}, {GL_FLOAT, "RGB float", fbuf}};
  for (int t = 0; t < 2; t++) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGB, 24, 8, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, rgb[t].buffer, rgb[t].type, W, H)) return 1;
    GLint alpha = -1;
    glGetIntegerv(GL_ALPHA_BITS, &alpha);
    printf("%-24s %d\n", rgb[t].name, alpha);
    draw();
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA);
    glColor4f(1, 1, 1, 1);
    glBegin(GL_TRIANGLES);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glEnd();
    glFinish();
    show("dst alpha blend", rgb[t].type, 3, W - 1, 3);
    OSMesaDestroyContext(ctx);
  }
  /* OSMESA_RGB_565: one GLushort a pixel, rounded to 5, 6 and 5 bits; the other types are
   * refused for it. */
  {
    static GLushort b565[W * H];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGB_565, 24, 8, 0, NULL);
    if (!ctx) return 1;
    printf("%-24s %d\n", "565 as ubyte", OSMesaMakeCurrent(ctx, bbuf, GL_UNSIGNED_BYTE, W, H));
    if (!OSMesaMakeCurrent(ctx, b565, GL_UNSIGNED_SHORT_5_6_5, W, H)) return 1;
    GLint bits[3];
    glGetIntegerv(GL_RED_BITS, &bits[0]);
    glGetIntegerv(GL_GREEN_BITS, &bits[1]);
    glGetIntegerv(GL_ALPHA_BITS, &bits[2]);
    printf("%-24s %d %d %d\n", "565 bits", bits[0], bits[1], bits[2]);
    draw();
    printf("%-24s 0x%04x 0x%04x 0x%04x\n", "565 flat clear smooth", b565[1 * W + 1],
           b565[3 * W + W - 1], b565[7 * W + 3]);
    OSMesaDestroyContext(ctx);
  }
  /* OSMESA_ROW_LENGTH and OSMESA_Y_UP on a byte buffer, RGBA and BGRA: rows of W + 3
   * pixels, the 3 beyond the image left as they were (0xAB); then row 0 at the top. */
  {
    enum { R = W + 3 };
    static GLubyte padded[R * H * 4];
    static const GLenum fmts[] = {OSMESA_RGBA, OSMESA_BGRA};
    for (int f = 0; f < 2; f++)
      for (int up = 1; up >= 0; up--) {
        memset(padded, 0xAB, sizeof padded);
        OSMesaContext ctx = OSMesaCreateContextExt(fmts[f], 24, 8, 0, NULL);
        if (!ctx || !OSMesaMakeCurrent(ctx, padded, GL_UNSIGNED_BYTE, W, H)) return 1;
        OSMesaPixelStore(OSMESA_ROW_LENGTH, R);
        OSMesaPixelStore(OSMESA_Y_UP, up);
        draw();
        const GLubyte *flat = padded + ((up ? 1 : H - 2) * R + 1) * 4;
        const GLubyte *smooth = padded + ((up ? 7 : 0) * R + 3) * 4;
        const GLubyte *pad = padded + (2 * R + W) * 4;
        printf("%s y_up %d: flat %u %u %u %u smooth %u %u %u %u pad %u %u\n",
               f ? "BGRA" : "RGBA", up, flat[0], flat[1], flat[2], flat[3], smooth[0],
               smooth[1], smooth[2], smooth[3], pad[0], pad[11]);
        OSMesaDestroyContext(ctx);
      }
  }
  return 0;
}
