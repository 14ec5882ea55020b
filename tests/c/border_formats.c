/* TEXTURE_BORDER_COLOR on textures of every base format: GL 1.5 §3.8.8 takes the border
 * colour as the texture's base format takes a colour (Table 3.15: ALPHA keeps A, LUMINANCE
 * and INTENSITY R, LUMINANCE_ALPHA R and A), so an ALPHA texture's border under MODULATE
 * gives the fragment's colour and its alpha times the border's alpha. Each format is drawn
 * twice: wholly in the border with CLAMP_TO_BORDER and NEAREST, and half texel, half border
 * with CLAMP and LINEAR. Run on Mesa's OSMesa and on fixedfunc's library, the printed lines
 * must be the same and the images match.
 *
 * usage: border_formats [out.ppm] */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 96
#define H 16
static GLubyte *buf;
static int panels;

/* The next 8x8 panel, every vertex at texture coordinates (s, t); its centre printed. */
static void panel(const char *what, float s, float t) {
  int x = (panels % 12) * 8, y = (panels / 12) * 8;
  panels++;
  glViewport(x, y, 8, 8);
  glBegin(GL_QUADS);
  glTexCoord2f(s, t); glVertex2f(-1, -1);
  glTexCoord2f(s, t); glVertex2f(1, -1);
  glTexCoord2f(s, t); glVertex2f(1, 1);
  glTexCoord2f(s, t); glVertex2f(-1, 1);
  glEnd();
  glFinish();
  const GLubyte *p = buf + 4 * ((y + 4) * W + x + 4);
  printf("%-36s %3d %3d %3d %3d err 0x%x\n", what, p[0], p[1], p[2], p[3], glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "border_formats.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  GLubyte texels[16 * 4];
  for (int i = 0; i < 16; i++) {
    texels[4 * i] = 200;
    texels[4 * i + 1] = 100;
    texels[4 * i + 2] = 50;
    texels[4 * i + 3] = 150;
  }
  const GLfloat border[4] = {0.9f, 0.3f, 0.6f, 0.4f};
  struct { GLint format; const char *name; } formats[] = {
      {GL_ALPHA, "ALPHA"}, {GL_LUMINANCE, "LUMINANCE"},
      {GL_LUMINANCE_ALPHA, "LUMINANCE_ALPHA"}, {GL_INTENSITY, "INTENSITY"},
      {GL_RGB, "RGB"}, {GL_RGBA, "RGBA"}, {GL_ALPHA8, "ALPHA8"},
      {GL_LUMINANCE8_ALPHA8, "LUMINANCE8_ALPHA8"}, {2, "component count 2"},
      {GL_ALPHA4, "ALPHA4"}, {GL_LUMINANCE4_ALPHA4, "LUMINANCE4_ALPHA4"},
      {GL_INTENSITY8, "INTENSITY8"},
  };
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor4f(0.8f, 0.9f, 1.0f, 0.7f);
  for (unsigned f = 0; f < sizeof formats / sizeof formats[0]; f++) {
    char what[64];
    glBindTexture(GL_TEXTURE_2D, f + 1);
    glTexImage2D(GL_TEXTURE_2D, 0, formats[f].format, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 texels);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    snprintf(what, sizeof what, "%s border", formats[f].name);
    panel(what, 2.5f, 0.5f);
  }
  for (unsigned f = 0; f < sizeof formats / sizeof formats[0]; f++) {
    char what[64];
    glBindTexture(GL_TEXTURE_2D, f + 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
    snprintf(what, sizeof what, "%s half border", formats[f].name);
    /* s = 1: halfway between the last texel and the border. */
    panel(what, 1.0f, 0.375f);
  }
  return finish(out, ctx, buf, W, H);
}
