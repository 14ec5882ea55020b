/* Uploads whose sizes GL refuses, from a short array: the call fails with its error and
 * reads nothing (Mesa checks the sizes, and a sub-image's region against its level, before
 * it touches the program's memory). The array is 64 bytes at the very end of a readable
 * page followed by an unreadable one, so a call that read past it would crash the
 * program. After the refused calls the texture still holds what it was given, and the
 * calls with the same array and sizes GL accepts succeed.
 *
 * usage: upload_bounds [out.ppm] */
#define _DEFAULT_SOURCE
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>
#include "report.h"
#define W 32
#define H 16

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "upload_bounds.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  long page = sysconf(_SC_PAGESIZE);
  GLubyte *pages = mmap(NULL, 2 * page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                        -1, 0);
  if (pages == MAP_FAILED || mprotect(pages + page, page, PROT_NONE) != 0) return 1;
  GLubyte *shortarray = pages + page - 64;
  for (int i = 0; i < 64; i++) shortarray[i] = (GLubyte)(i * 4);

  GLuint tex = replace_texture_panels();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, shortarray);
  err("4x4 from 64 bytes");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16385, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, shortarray);
  err("2D width 16385");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 20000, 0, GL_RGBA, GL_UNSIGNED_BYTE, shortarray);
  err("2D height 20000");
  glTexImage2D(GL_TEXTURE_2D, 3, GL_RGBA, 4096, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, shortarray);
  err("2D level 3 width 4096");
  glTexImage2D(GL_TEXTURE_2D, 15, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, shortarray);
  err("2D level 15");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, shortarray);
  err("2D border 2");
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 16385, 16385, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, shortarray);
  err("cube face 16385");
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 16385, 0, GL_RGBA, GL_UNSIGNED_BYTE, shortarray);
  err("1D width 16385");
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2049, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               shortarray);
  err("3D width 2049");
  glTexImage3D(GL_TEXTURE_3D, 1, GL_RGBA, 2, 2, 1025, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               shortarray);
  err("3D level 1 depth 1025");
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 2048, 2048, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               shortarray);
  err("proxy 3D 2048x2048x2");

  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1000, 1, GL_RGBA, GL_UNSIGNED_BYTE, shortarray);
  err("sub-image 1000 wide into 4x4");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 400, GL_RGBA, GL_UNSIGNED_BYTE, shortarray);
  err("sub-image 400 high into 4x4");
  glTexSubImage2D(GL_TEXTURE_2D, 2, 0, 0, 1000, 1, GL_RGBA, GL_UNSIGNED_BYTE, shortarray);
  err("sub-image of a missing level");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 2, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, shortarray + 48);
  err("sub-image 2x2 at (2,2)");

  GLuint other[2];
  glGenTextures(2, other);
  glBindTexture(GL_TEXTURE_1D, other[0]);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, shortarray);
  glTexSubImage1D(GL_TEXTURE_1D, 0, 0, 100000, GL_RGBA, GL_UNSIGNED_BYTE, shortarray);
  err("1D sub-image 100000 wide");
  glBindTexture(GL_TEXTURE_3D, other[1]);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, shortarray);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 2, 2, 300, GL_RGBA, GL_UNSIGNED_BYTE,
                  shortarray);
  err("3D sub-image 300 deep");

  /* DXT1: 8 bytes a 4x4 block; a 256x256 region is 32768 bytes, the array 64. */
  glBindTexture(GL_TEXTURE_2D, tex);
  GLuint dxt;
  glGenTextures(1, &dxt);
  glBindTexture(GL_TEXTURE_2D, dxt);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 8, 0, 32,
                         shortarray);
  err("DXT1 8x8");
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 256, 256, GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
                            32768, shortarray);
  err("DXT1 sub-image 256x256 into 8x8");

  glBindTexture(GL_TEXTURE_2D, tex);
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0); glVertex2f(-1, -1);
  glTexCoord2f(1, 0); glVertex2f(0, -1);
  glTexCoord2f(1, 1); glVertex2f(0, 1);
  glTexCoord2f(0, 1); glVertex2f(-1, 1);
  glEnd();
  glFinish();
  GLubyte texels[64];
  memset(texels, 0, sizeof texels);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  printf("texels");
  for (int i = 0; i < 64; i += 4) printf(" %d", texels[i]);
  printf("\n");
  err("drawn");
  return finish(out, ctx, buf, W, H);
}
