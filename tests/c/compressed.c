/* GL 1.3's compressed textures in the S3TC formats: glCompressedTexImage2D of DXT1 (RGB
 * and RGBA), DXT3 and DXT5 blocks of pseudo-random bits, read back decoded with
 * glGetTexImage and as blocks with glGetCompressedTexImage, drawn into panels; the level
 * queries, sub-images, display lists, the compression hint and the errors of each call.
 * Run on Mesa's OSMesa and on fixedfunc's library, the printed lines must be the same and
 * the images match.
 *
 * usage: compressed [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"
#define W 64
#define H 32
static GLubyte *buf;
static int panels;
static unsigned seed = 12345;

static GLubyte next(void) {
  seed = seed * 1103515245u + 12345u;
  return (GLubyte)(seed >> 16);
}

/* A panel drawn with the bound texture (REPLACE, NEAREST). */
static void panel(void) {
  glViewport((panels % 8) * 8, (panels / 8) * 8, 8, 8);
  panels++;
  glEnable(GL_TEXTURE_2D);
  glRectf(-1, -1, 1, 1);
  glDisable(GL_TEXTURE_2D);
  glViewport(0, 0, W, H);
}

/* Level 0's queries, its texels (a sum and the first eight bytes) and whether its blocks
 * come back as given. */
static void level(const char *what, const GLubyte *blocks, int size, int w, int h) {
  GLint compressed = -1, image = -1, internal = -1, red = -1, alpha = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &compressed);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &image);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &red);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_ALPHA_SIZE, &alpha);
  /* The internal format of a generic name is left out: Mesa answers the base name it was
   * given (GL_ALPHA), the layer the sized format it keeps (GL_ALPHA8), as for GL_RGBA. */
  printf("%-30s compressed %d size %d format 0x%x bits %d %d err %x\n", what, compressed, image,
         blocks ? internal : 0, red, alpha, glGetError());
  GLubyte *t = calloc((size_t)w * h, 4);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  unsigned long sum = 0;
  for (int i = 0; i < w * h * 4; i++) sum = sum * 31 + t[i];
  printf("%-30s texels %lu:", what, sum);
  for (int i = 0; i < 8; i++) printf(" %d", t[i]);
  printf(" err %x\n", glGetError());
  free(t);
  if (blocks) {
    GLubyte *back = malloc(size + 4);
    memset(back, 0xee, size + 4);
    glGetCompressedTexImage(GL_TEXTURE_2D, 0, back);
    printf("%-30s blocks back %s, after them %s err %x\n", what,
           memcmp(back, blocks, size) ? "differ" : "same",
           back[size] == 0xee ? "untouched" : "written", glGetError());
    free(back);
  }
  panel();
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "compressed.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  replace_texture_panels();

  /* The formats Mesa lists that the layer decodes. */
  GLint n = 0, formats[64];
  glGetIntegerv(GL_NUM_COMPRESSED_TEXTURE_FORMATS, &n);
  glGetIntegerv(GL_COMPRESSED_TEXTURE_FORMATS, formats);
  int dxt1 = 0, dxt3 = 0, dxt5 = 0;
  for (int i = 0; i < n && i < 64; i++) {
    dxt1 |= formats[i] == GL_COMPRESSED_RGB_S3TC_DXT1_EXT;
    dxt3 |= formats[i] == GL_COMPRESSED_RGBA_S3TC_DXT3_EXT;
    dxt5 |= formats[i] == GL_COMPRESSED_RGBA_S3TC_DXT5_EXT;
  }
  printf("listed DXT1 %d DXT3 %d DXT5 %d err %x\n", dxt1, dxt3, dxt5, glGetError());

  /* The hint: its default, a value kept, a bad mode refused, HINT_BIT restoring it. */
  ints("TEXTURE_COMPRESSION_HINT", GL_TEXTURE_COMPRESSION_HINT);
  glHint(GL_TEXTURE_COMPRESSION_HINT, GL_NICEST);
  glPushAttrib(GL_HINT_BIT);
  glHint(GL_TEXTURE_COMPRESSION_HINT, GL_FASTEST);
  ints("hint set FASTEST", GL_TEXTURE_COMPRESSION_HINT);
  glHint(GL_TEXTURE_COMPRESSION_HINT, GL_RGBA);
  err("hint GL_RGBA");
  glPopAttrib();
  ints("hint popped", GL_TEXTURE_COMPRESSION_HINT);

  /* Every format, random blocks, 8×8 and 5×5. */
  static const struct { GLenum format; const char *name; int block; } s3tc[] = {
      {GL_COMPRESSED_RGB_S3TC_DXT1_EXT, "RGB_DXT1", 8},
      {GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, "RGBA_DXT1", 8},
      {GL_COMPRESSED_RGBA_S3TC_DXT3_EXT, "DXT3", 16},
      {GL_COMPRESSED_RGBA_S3TC_DXT5_EXT, "DXT5", 16},
  };
  GLubyte blocks[16 * 16];
  for (int f = 0; f < 4; f++) {
    for (int round = 0; round < 3; round++) {
      int size = 4 * s3tc[f].block;
      for (int i = 0; i < size; i++) blocks[i] = next();
      if (round == 2) {
        /* Equal and ordered endpoints: the three-colour blocks of DXT1. */
        int c = s3tc[f].block == 16 ? 8 : 0;
        blocks[c] = blocks[c + 2];
        blocks[c + 1] = blocks[c + 3];
      }
      glCompressedTexImage2D(GL_TEXTURE_2D, 0, s3tc[f].format, 8, 8, 0, size, blocks);
      char name[40];
      snprintf(name, sizeof name, "%s 8x8 #%d", s3tc[f].name, round);
      level(name, blocks, size, 8, 8);
    }
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, s3tc[f].format, 5, 5, 0, 4 * s3tc[f].block, blocks);
    char name[40];
    snprintf(name, sizeof name, "%s 5x5", s3tc[f].name);
    level(name, blocks, 4 * s3tc[f].block, 5, 5);
  }

  /* Sub-images: a block replaced, then the errors of partial and foreign blocks. */
  GLubyte big[16 * 8];
  for (int i = 0; i < 16 * 8; i++) big[i] = next();
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 16, 16, 0, 128, big);
  err("16x16 DXT1");
  GLubyte one[8] = {0x1f, 0xf8, 0xe0, 0x07, 0x1b, 0x1b, 0x1b, 0x1b};
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 8, 4, 4, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, one);
  err("sub-image at (4, 8)");
  memcpy(big + 8 * (2 * 4 + 1), one, 8);
  level("after the sub-image", big, 128, 16, 16);
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 4, 4, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, one);
  err("sub-image at (2, 0)");
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, one);
  err("sub-image 2x2 inside");
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 12, 12, 4, 4, GL_COMPRESSED_RGBA_S3TC_DXT5_EXT, 16,
                            big);
  err("sub-image in DXT5");
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 16, 0, 4, 4, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, one);
  err("sub-image outside");
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 7, one);
  err("sub-image size 7");
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_COMPRESSED_RGB, 8, one);
  err("sub-image generic format");
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, 8, one);
  err("sub-image RGBA format");
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 3, 0, 0, 4, 4, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, one);
  err("sub-image of level 3");

  /* The errors of glCompressedTexImage2D. */
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 8, 0, 31, blocks);
  err("image size 31");
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 8, 0, -1, blocks);
  err("image size -1");
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 8, 8, 0, 32, blocks);
  err("generic COMPRESSED_RGB");
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, 32, blocks);
  err("uncompressed RGBA");
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 8, 1, 32, blocks);
  err("border 1");
  glCompressedTexImage2D(GL_TEXTURE_2D, 15, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 8, 0, 32, blocks);
  err("level 15");
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, -4, 8, 0, 32, blocks);
  err("width -4");
  glCompressedTexImage2D(GL_TEXTURE_1D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 8, 0, 32, blocks);
  err("target TEXTURE_1D");
  glCompressedTexImage1D(GL_TEXTURE_1D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 0, 8, blocks);
  err("glCompressedTexImage1D");
  glCompressedTexImage3D(GL_TEXTURE_3D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 8, 1, 0, 32,
                         blocks);
  err("glCompressedTexImage3D");
  glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 8, 0, 32,
                         NULL);
  err("proxy");

  /* glGetCompressedTexImage of what has no blocks. */
  GLubyte scratch[256];
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, blocks);
  glGetCompressedTexImage(GL_TEXTURE_2D, 0, scratch);
  err("get blocks of RGBA");
  glGetCompressedTexImage(GL_TEXTURE_2D, 5, scratch);
  err("get blocks of level 5");
  glGetCompressedTexImage(GL_TEXTURE_2D, -1, scratch);
  err("get blocks of level -1");
  glGetCompressedTexImage(GL_PROXY_TEXTURE_2D, 0, scratch);
  err("get blocks of the proxy");
  GLint image = -7;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &image);
  printf("%-40s %d err 0x%x\n", "image size of RGBA", image, glGetError());

  /* Generic formats Mesa keeps uncompressed. */
  glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_ALPHA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, blocks);
  level("generic COMPRESSED_ALPHA", NULL, 0, 2, 2);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_INTENSITY, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               blocks);
  level("generic COMPRESSED_INTENSITY", NULL, 0, 2, 2);

  /* A display list keeps the blocks of its compile. */
  GLuint list = glGenLists(1);
  for (int i = 0; i < 32; i++) blocks[i] = next();
  glNewList(list, GL_COMPILE);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, 8, 8, 0, 32, blocks);
  glCompressedTexImage2D(GL_TEXTURE_2D, 1, GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, 4, 4, 0, 9, blocks);
  glEndList();
  GLint width = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
  printf("%-40s %d err 0x%x\n", "width before the list", width, glGetError());
  GLubyte kept[32];
  memcpy(kept, blocks, 32);
  memset(blocks, 0, 32);
  glCallList(list);
  err("the list run");
  level("the list's image", kept, 32, 8, 8);

  glViewport(0, 0, W, H);
  return finish(out, ctx, buf, W, H);
}
