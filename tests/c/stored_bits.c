/* glGetTexImage in types wider than a byte, of textures whose storage is not 8 bits a
 * component: packed formats (RGBA4, RGB5, R3_G3_B2, RGB10_A2, LUMINANCE4_ALPHA4), which
 * Mesa unpacks through floats, and 16-bit ones (RGBA16, LUMINANCE16), which it widens as
 * integers — from 8-bit and from 16-bit data. One line per format, data and type: the
 * error and the values of the first three texels. Then glReadPixels of an RGBA32F
 * framebuffer object as INT and UNSIGNED_INT (1.0 wraps to INT_MIN and to 0).
 *
 * usage: stored_bits */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>
#include <string.h>

#include "report.h"

#define TEXELS 3

static const struct {
  const char *name;
  GLenum format;
} FORMATS[] = {
    {"RGBA4", GL_RGBA4},           {"RGB5", GL_RGB5},         {"R3_G3_B2", GL_R3_G3_B2},
    {"RGB10_A2", GL_RGB10_A2},     {"RGBA16", GL_RGBA16},     {"LUMINANCE16", GL_LUMINANCE16},
    {"LUMINANCE4_ALPHA4", GL_LUMINANCE4_ALPHA4},
};

static const struct {
  const char *name;
  GLenum type;
} TYPES[] = {
    {"UNSIGNED_SHORT", GL_UNSIGNED_SHORT}, {"UNSIGNED_INT", GL_UNSIGNED_INT},
    {"INT", GL_INT},                       {"FLOAT", GL_FLOAT},
    {"SHORT", GL_SHORT},                   {"UNSIGNED_SHORT_4_4_4_4", GL_UNSIGNED_SHORT_4_4_4_4},
};

/* The first TEXELS texels read as RGBA in `type`, printed as integers (floats as their
 * bits) after the error. */
static void texels(const char *format, const char *data, int t) {
  GLuint out[4 * 4 * 4]; /* the whole 4×4 level, 16 bytes a texel at most */
  memset(out, 0xab, sizeof out);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, TYPES[t].type, out);
  printf("%-18s %-6s %-22s err 0x%x:", format, data, TYPES[t].name, glGetError());
  int n = TYPES[t].type == GL_UNSIGNED_SHORT || TYPES[t].type == GL_SHORT ? 2 * TEXELS
          : TYPES[t].type == GL_UNSIGNED_SHORT_4_4_4_4                    ? (TEXELS + 1) / 2
                                                                           : 4 * TEXELS;
  for (int i = 0; i < n; i++) printf(" %08x", out[i]);
  printf("\n");
}

int main(void) {
  static GLubyte buffer[16 * 16 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 16, 16)) return 1;
  GLubyte bytes[4 * 4 * 4];
  GLushort shorts[4 * 4 * 4];
  for (int i = 0; i < 64; i++) {
    bytes[i] = (GLubyte)(i * 37 + 3);
    shorts[i] = (GLushort)(i * 4099 + 777);
  }
  for (size_t f = 0; f < sizeof FORMATS / sizeof FORMATS[0]; f++) {
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    for (int d = 0; d < 2; d++) {
      if (d == 0)
        glTexImage2D(GL_TEXTURE_2D, 0, FORMATS[f].format, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, bytes);
      else
        glTexImage2D(GL_TEXTURE_2D, 0, FORMATS[f].format, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT,
                     shorts);
      for (size_t t = 0; t < sizeof TYPES / sizeof TYPES[0]; t++)
        texels(FORMATS[f].name, d == 0 ? "bytes" : "shorts", (int)t);
    }
    glDeleteTextures(1, &tex);
  }

  GLuint fb, rb;
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, 4, 4);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  glClearColor(1, 0.5333f, 0.1f, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  GLint ints[4];
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_INT, ints);
  printf("%-40s err 0x%x: %d %d %d %d\n", "RGBA32F read as INT", glGetError(), ints[0], ints[1],
         ints[2], ints[3]);
  GLuint uints[4];
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT, uints);
  printf("%-40s err 0x%x: %u %u %u %u\n", "RGBA32F read as UNSIGNED_INT", glGetError(), uints[0],
         uints[1], uints[2], uints[3]);
  OSMesaDestroyContext(ctx);
  return 0;
}
