/* GL 1.2's 3D textures (EXT_texture3D) as volume-rendering programs of the era used them:
 * glTexImage3D, glTexSubImage3D and glCopyTexSubImage3D with their errors, the
 * TEXTURE_3D enable and its precedence over 2D, TEXTURE_WRAP_R, TEXTURE_DEPTH,
 * MAX_3D_TEXTURE_SIZE, PROXY_TEXTURE_3D, the unpack and pack IMAGE_HEIGHT and SKIP_IMAGES,
 * glGetTexImage of a volume, mipmaps (given and generated), the attribute stack, display
 * lists and glFramebufferTexture3D; then panels that sample a volume: its images by r,
 * LINEAR between images, r from texgen OBJECT_LINEAR in perspective, wrap R, a mipmapped
 * volume minified, patches by glTexSubImage3D and glCopyTexSubImage3D, and an image drawn
 * into through a framebuffer object. Run on Mesa's OSMesa and on fixedfunc's library, the
 * printed lines must be the same and the images match.
 *
 * usage: tex3d [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"

#define W 128
#define H 64
#define P 16

static GLubyte volume[4 * 4 * 4 * 4];
static GLubyte scratch[4096];

/* Texel (x, y, z): each image z a colour of its own, x and y a ramp. */
static void fill_volume(void) {
  static const GLubyte base[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}};
  for (int z = 0; z < 4; z++)
    for (int y = 0; y < 4; y++)
      for (int x = 0; x < 4; x++) {
        GLubyte *t = volume + 4 * (x + 4 * (y + 4 * z));
        int ramp = 40 + 50 * x + 20 * y;
        for (int c = 0; c < 3; c++) {
          int v = ramp / (c + 2);
          t[c] = base[z][c] > v ? base[z][c] : (GLubyte)v;
        }
        t[3] = 255;
      }
}

static void level(const char *what, GLenum target, int lvl, GLenum pname) {
  GLint v = -7;
  glGetTexLevelParameteriv(target, lvl, pname, &v);
  printf("%-40s %d  err 0x%x\n", what, v, glGetError());
}

static void bytes(const char *what, const GLubyte *b, int n) {
  printf("%-40s", what);
  for (int i = 0; i < n; i++) printf(" %d", b[i]);
  printf("\n");
}

static void image3d(GLenum target, int lvl, GLint internal, int w, int h, int d, int border,
                    GLenum format, GLenum type, const void *data, const char *what) {
  glTexImage3D(target, lvl, internal, w, h, d, border, format, type, data);
  err(what);
}

static void errors_and_queries(void) {
  const char *ext = (const char *)glGetString(GL_EXTENSIONS);
  printf("%-40s %d\n", "GL_EXT_texture3D listed", strstr(ext, "GL_EXT_texture3D ") != NULL);
  ints("MAX_3D_TEXTURE_SIZE", GL_MAX_3D_TEXTURE_SIZE);
  ints("TEXTURE_BINDING_3D", GL_TEXTURE_BINDING_3D);
  ints("TEXTURE_3D enabled", GL_TEXTURE_3D);
  ints("UNPACK_IMAGE_HEIGHT", GL_UNPACK_IMAGE_HEIGHT);
  ints("UNPACK_SKIP_IMAGES", GL_UNPACK_SKIP_IMAGES);
  ints("PACK_IMAGE_HEIGHT", GL_PACK_IMAGE_HEIGHT);
  ints("PACK_SKIP_IMAGES", GL_PACK_SKIP_IMAGES);
  const GLenum RGBA = GL_RGBA, UB = GL_UNSIGNED_BYTE;
  image3d(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 4, 0, RGBA, UB, volume, "glTexImage3D(TEXTURE_2D)");
  image3d(GL_TEXTURE_3D, -1, GL_RGBA8, 4, 4, 4, 0, RGBA, UB, volume, "level -1");
  image3d(GL_TEXTURE_3D, 12, GL_RGBA8, 1, 1, 1, 0, RGBA, UB, volume, "level 12");
  image3d(GL_TEXTURE_3D, 11, GL_RGBA8, 1, 1, 1, 0, RGBA, UB, volume, "level 11");
  image3d(GL_TEXTURE_3D, 0, GL_RGBA8, 4, 4, -1, 0, RGBA, UB, volume, "depth -1");
  image3d(GL_TEXTURE_3D, 0, GL_RGBA8, 4, 4, 3000, 0, RGBA, UB, NULL, "depth 3000");
  image3d(GL_TEXTURE_3D, 0, GL_RGBA8, 2049, 1, 1, 0, RGBA, UB, NULL, "width 2049");
  image3d(GL_TEXTURE_3D, 1, GL_RGBA8, 2048, 1, 1, 0, RGBA, UB, NULL, "level 1 width 2048");
  image3d(GL_TEXTURE_3D, 1, GL_RGBA8, 1024, 1, 1, 0, RGBA, UB, NULL, "level 1 width 1024");
  image3d(GL_TEXTURE_3D, 0, GL_RGBA8, 4, 4, 4, 2, RGBA, UB, NULL, "border 2");
  image3d(GL_TEXTURE_3D, 0, 0x1234, 4, 4, 4, 0, RGBA, UB, NULL, "bad internal format");
  image3d(GL_TEXTURE_3D, 0, GL_RGBA8, 4, 4, 4, 0, 0x1234, UB, NULL, "bad format");
  image3d(GL_TEXTURE_3D, 0, GL_RGBA8, 4, 4, 4, 0, RGBA, 0x1234, NULL, "bad type");
  image3d(GL_TEXTURE_3D, 0, GL_DEPTH_COMPONENT24, 4, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
          NULL, "a depth format");
  image3d(GL_TEXTURE_3D, 0, GL_RGBA8, 4, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL,
          "DEPTH_COMPONENT data, RGBA8");
  image3d(GL_TEXTURE_3D, 0, GL_RGBA8, 4, 4, 4, 0, GL_STENCIL_INDEX, UB, NULL,
          "STENCIL_INDEX data");
  image3d(GL_TEXTURE_3D, 0, GL_RGBA8, 0, 0, 0, 0, RGBA, UB, NULL, "0x0x0");
  image3d(GL_TEXTURE_3D, 0, GL_RGBA8, 3, 5, 7, 0, RGBA, UB, NULL, "3x5x7");
  level("its TEXTURE_DEPTH", GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH);
  image3d(GL_TEXTURE_3D, 0, GL_RGBA8, 4, 4, 4, 0, RGBA, UB, volume, "4x4x4 RGBA8");
  level("TEXTURE_WIDTH", GL_TEXTURE_3D, 0, GL_TEXTURE_WIDTH);
  level("TEXTURE_DEPTH", GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH);
  level("TEXTURE_RED_SIZE", GL_TEXTURE_3D, 0, GL_TEXTURE_RED_SIZE);
  level("TEXTURE_DEPTH of level 11", GL_TEXTURE_3D, 11, GL_TEXTURE_DEPTH);
  level("TEXTURE_DEPTH of level 12", GL_TEXTURE_3D, 12, GL_TEXTURE_DEPTH);
  level("TEXTURE_DEPTH of an unspecified 2D", GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, RGBA, UB, volume);
  level("TEXTURE_DEPTH of a 2D image", GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH);
  level("TEXTURE_DEPTH of 2D level 14", GL_TEXTURE_2D, 14, GL_TEXTURE_DEPTH);

  /* Sub-images and copies. */
  glTexSubImage3D(GL_TEXTURE_3D, 0, 1, 1, 1, 2, 2, 2, RGBA, UB, volume);
  err("glTexSubImage3D 2x2x2 at (1,1,1)");
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 3, 2, 2, 2, RGBA, UB, volume);
  err("glTexSubImage3D past the depth");
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, -1, 1, 1, 1, RGBA, UB, volume);
  err("glTexSubImage3D zoffset -1");
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 1, 1, -1, RGBA, UB, volume);
  err("glTexSubImage3D depth -1");
  glTexSubImage3D(GL_TEXTURE_3D, 2, 0, 0, 0, 1, 1, 1, RGBA, UB, volume);
  err("glTexSubImage3D of an unspecified level");
  glTexSubImage3D(GL_TEXTURE_3D, 12, 0, 0, 0, 1, 1, 1, RGBA, UB, volume);
  err("glTexSubImage3D level 12");
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, volume);
  err("glTexSubImage3D DEPTH_COMPONENT data");
  glTexSubImage3D(GL_TEXTURE_2D, 0, 0, 0, 0, 1, 1, 1, RGBA, UB, volume);
  err("glTexSubImage3D(TEXTURE_2D)");
  glTexSubImage3D(GL_TEXTURE_3D, 0, 4, 0, 0, 0, 1, 1, RGBA, UB, volume);
  err("glTexSubImage3D empty at the edge");
  glTexSubImage3D(GL_TEXTURE_3D, 0, 5, 0, 0, 0, 1, 1, RGBA, UB, volume);
  err("glTexSubImage3D empty past the edge");
  glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 1, 0, 0, 2, 2);
  err("glCopyTexSubImage3D into image 1");
  glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 4, 0, 0, 2, 2);
  err("glCopyTexSubImage3D zoffset 4");
  glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, -1, 0, 0, 2, 2);
  err("glCopyTexSubImage3D zoffset -1");
  glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 3, 0, 0, 0, 0, 2, 2);
  err("glCopyTexSubImage3D past the width");
  glCopyTexSubImage3D(GL_TEXTURE_3D, 2, 0, 0, 0, 0, 0, 1, 1);
  err("glCopyTexSubImage3D unspecified level");
  glCopyTexSubImage3D(GL_TEXTURE_3D, 12, 0, 0, 0, 0, 0, 1, 1);
  err("glCopyTexSubImage3D level 12");
  glCopyTexSubImage3D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 0, 1, 1);
  err("glCopyTexSubImage3D(TEXTURE_2D)");

  /* Parameters, the enable, bindings. */
  GLint v = -7;
  glGetTexParameteriv(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, &v);
  printf("%-40s 0x%x\n", "initial TEXTURE_WRAP_R", v);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  err("WRAP_R CLAMP_TO_EDGE");
  glGetTexParameteriv(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, &v);
  printf("%-40s 0x%x\n", "TEXTURE_WRAP_R", v);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_LINEAR);
  err("WRAP_R LINEAR");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R, GL_CLAMP);
  err("WRAP_R of a 2D texture");
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R, &v);
  printf("%-40s 0x%x\n", "its TEXTURE_WRAP_R", v);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_BORDER);
  err("WRAP_R CLAMP_TO_BORDER");
  glEnable(GL_TEXTURE_3D);
  err("glEnable(TEXTURE_3D)");
  ints("TEXTURE_3D enabled", GL_TEXTURE_3D);
  glBindTexture(GL_TEXTURE_2D, 5);
  glBindTexture(GL_TEXTURE_3D, 5);
  err("bind a 2D name to TEXTURE_3D");
  glBindTexture(GL_TEXTURE_3D, 6);
  ints("TEXTURE_BINDING_3D", GL_TEXTURE_BINDING_3D);
  ints("TEXTURE_BINDING_2D", GL_TEXTURE_BINDING_2D);
  glGenerateMipmap(GL_TEXTURE_3D);
  err("glGenerateMipmap without an image");
  glPushAttrib(GL_TEXTURE_BIT);
  glBindTexture(GL_TEXTURE_3D, 7);
  glDisable(GL_TEXTURE_3D);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP);
  glPopAttrib();
  ints("TEXTURE_BINDING_3D after glPopAttrib", GL_TEXTURE_BINDING_3D);
  ints("TEXTURE_3D after glPopAttrib", GL_TEXTURE_3D);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_TEXTURE_3D);
  glPopAttrib();
  ints("TEXTURE_3D after an ENABLE_BIT pop", GL_TEXTURE_3D);
  glPushAttrib(GL_TEXTURE_BIT);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP);
  glPopAttrib();
  glGetTexParameteriv(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, &v);
  printf("%-40s 0x%x\n", "TEXTURE_WRAP_R after glPopAttrib", v);
  glDisable(GL_TEXTURE_3D);
  glBegin(GL_POINTS);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 1, 1, 1, 0, RGBA, UB, volume);
  glEnd();
  err("glTexImage3D inside glBegin");

  /* Proxies. */
  image3d(GL_PROXY_TEXTURE_3D, 0, GL_RGBA8, 64, 32, 16, 0, RGBA, UB, NULL, "proxy 64x32x16");
  level("proxy TEXTURE_WIDTH", GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH);
  level("proxy TEXTURE_DEPTH", GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_DEPTH);
  level("proxy TEXTURE_GREEN_SIZE", GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_GREEN_SIZE);
  image3d(GL_PROXY_TEXTURE_3D, 0, GL_RGBA8, 4096, 1, 1, 0, RGBA, UB, NULL, "proxy 4096 wide");
  level("proxy TEXTURE_WIDTH", GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH);
  level("proxy TEXTURE_INTERNAL_FORMAT", GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_INTERNAL_FORMAT);
  image3d(GL_PROXY_TEXTURE_3D, 1, GL_RGBA8, 2048, 1, 1, 0, RGBA, UB, NULL,
          "proxy level 1 2048 wide");
  level("proxy level 1 TEXTURE_WIDTH", GL_PROXY_TEXTURE_3D, 1, GL_TEXTURE_WIDTH);
  image3d(GL_PROXY_TEXTURE_3D, 0, GL_RGBA8, 8, 8, 8, 0, RGBA, UB, NULL, "proxy 8x8x8");
  image3d(GL_PROXY_TEXTURE_3D, 0, GL_RGBA8, -1, 8, 8, 0, RGBA, UB, NULL, "proxy width -1");
  image3d(GL_PROXY_TEXTURE_3D, 12, GL_RGBA8, 1, 1, 1, 0, RGBA, UB, NULL, "proxy level 12");
  image3d(GL_PROXY_TEXTURE_3D, 0, GL_DEPTH_COMPONENT24, 4, 4, 4, 0, GL_DEPTH_COMPONENT,
          GL_FLOAT, NULL, "proxy of a depth format");
  level("proxy TEXTURE_WIDTH still", GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH);
  glGetTexParameteriv(GL_PROXY_TEXTURE_3D, GL_TEXTURE_WRAP_R, &v);
  err("glGetTexParameteriv(PROXY_TEXTURE_3D)");
  glTexParameteri(GL_PROXY_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_REPEAT);
  err("glTexParameteri(PROXY_TEXTURE_3D)");
  glBindTexture(GL_PROXY_TEXTURE_3D, 9);
  err("glBindTexture(PROXY_TEXTURE_3D)");
  glTexSubImage3D(GL_PROXY_TEXTURE_3D, 0, 0, 0, 0, 1, 1, 1, RGBA, UB, volume);
  err("glTexSubImage3D(PROXY_TEXTURE_3D)");
  glGetTexImage(GL_PROXY_TEXTURE_3D, 0, RGBA, UB, scratch);
  err("glGetTexImage(PROXY_TEXTURE_3D)");

  /* Pixel storage: a 2x2x2 LUMINANCE volume read with IMAGE_HEIGHT 3, SKIP_IMAGES 1 and
   * SKIP_ROWS 1, read back with and without the pack image parameters. */
  GLubyte in[64], out[64];
  for (int i = 0; i < 64; i++) in[i] = (GLubyte)i;
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, -1);
  err("UNPACK_IMAGE_HEIGHT -1");
  glPixelStorei(GL_PACK_SKIP_IMAGES, -1);
  err("PACK_SKIP_IMAGES -1");
  glBindTexture(GL_TEXTURE_3D, 8);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 3);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  ints("UNPACK_IMAGE_HEIGHT", GL_UNPACK_IMAGE_HEIGHT);
  ints("UNPACK_SKIP_IMAGES", GL_UNPACK_SKIP_IMAGES);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_LUMINANCE8, 2, 2, 2, 0, GL_LUMINANCE, UB, in);
  err("glTexImage3D, image height 3, skip 1");
  /* A 2D image ignores both. */
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE8, 2, 2, 0, GL_LUMINANCE, UB, in);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 2);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 1, 0, 1, 1, 2, 1, GL_LUMINANCE, UB, in);
  err("glTexSubImage3D, skip 2 images");
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  memset(out, 0xEE, sizeof out);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_LUMINANCE, UB, out);
  bytes("the volume (PACK_ALIGNMENT 4)", out, 16);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_IMAGE_HEIGHT, 3);
  glPixelStorei(GL_PACK_SKIP_IMAGES, 1);
  memset(out, 0xEE, sizeof out);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_LUMINANCE, UB, out);
  bytes("packed with image height 3, skip 1", out, 20);
  memset(out, 0xEE, sizeof out);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, UB, out);
  bytes("the 2D image, the same parameters", out, 6);
  glPixelStorei(GL_PACK_IMAGE_HEIGHT, 0);
  glPixelStorei(GL_PACK_SKIP_IMAGES, 0);
  memset(out, 0xEE, sizeof out);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_FLOAT, (GLfloat *)(void *)scratch);
  printf("%-40s %.4f %.4f  err 0x%x\n", "as RGBA floats, texel 1", ((GLfloat *)(void *)scratch)[4],
         ((GLfloat *)(void *)scratch)[7], glGetError());
  glGetTexImage(GL_TEXTURE_3D, 12, GL_RGBA, UB, out);
  err("glGetTexImage level 12");

  /* Mipmaps: GENERATE_MIPMAP and glGenerateMipmap halve the depth too. */
  glTexParameteri(GL_TEXTURE_3D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 4, 2, 8, 0, RGBA, UB, NULL);
  level("GENERATE_MIPMAP level 3 depth", GL_TEXTURE_3D, 3, GL_TEXTURE_DEPTH);
  level("GENERATE_MIPMAP level 3 width", GL_TEXTURE_3D, 3, GL_TEXTURE_WIDTH);
  level("GENERATE_MIPMAP level 4 width", GL_TEXTURE_3D, 4, GL_TEXTURE_WIDTH);
  glTexParameteri(GL_TEXTURE_3D, GL_GENERATE_MIPMAP, GL_FALSE);
  glBindTexture(GL_TEXTURE_3D, 9);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 2, 8, 4, 0, RGBA, UB, NULL);
  glGenerateMipmap(GL_TEXTURE_3D);
  err("glGenerateMipmap(TEXTURE_3D)");
  level("level 2 depth", GL_TEXTURE_3D, 2, GL_TEXTURE_DEPTH);
  level("level 3 height", GL_TEXTURE_3D, 3, GL_TEXTURE_HEIGHT);

  /* Display lists keep the data read at compile time; a proxy runs at once. */
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_LUMINANCE8, 2, 2, 2, 0, GL_LUMINANCE, UB, in);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 1, 1, 1, GL_LUMINANCE, UB, in + 40);
  glTexImage3D(GL_TEXTURE_3D, -1, GL_LUMINANCE8, 2, 2, 2, 0, GL_LUMINANCE, UB, in);
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA8, 16, 16, 16, 0, RGBA, UB, NULL);
  glEndList();
  err("a list of 3D calls");
  level("proxy width while compiling", GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH);
  in[0] = 200;
  in[40] = 201;
  glCallList(list);
  err("glCallList");
  memset(out, 0xEE, sizeof out);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_LUMINANCE, UB, out);
  bytes("what the list gave", out, 8);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

/* glFramebufferTexture3D: errors, answers, completeness. */
static void framebuffer_3d(void) {
  GLuint fb, t3, t2;
  GLint v = -7;
  glGenFramebuffers(1, &fb);
  glGenTextures(1, &t3);
  glGenTextures(1, &t2);
  glBindTexture(GL_TEXTURE_2D, t2);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glBindTexture(GL_TEXTURE_3D, t3);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 8, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, t3, 0, 2);
  err("glFramebufferTexture3D zoffset 2");
  printf("%-40s 0x%x\n", "status", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_3D_ZOFFSET_EXT, &v);
  printf("%-40s %d  err 0x%x\n", "ATTACHMENT_TEXTURE_3D_ZOFFSET", v, glGetError());
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &v);
  printf("%-40s 0x%x  err 0x%x\n", "ATTACHMENT_OBJECT_TYPE", v, glGetError());
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                        GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &v);
  printf("%-40s %d  err 0x%x\n", "ATTACHMENT_TEXTURE_LEVEL", v, glGetError());
  glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, t3, 0, 4);
  err("zoffset 4 (the depth)");
  printf("%-40s 0x%x\n", "status", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, t3, 0, 2048);
  err("zoffset 2048");
  glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, t3, 0, -1);
  err("zoffset -1");
  glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t3, 0, 0);
  err("textarget TEXTURE_2D");
  glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, t3, 12, 0);
  err("level 12");
  glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, 999, 0, 0);
  err("a name with no texture");
  glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, t2, 0, 0);
  err("a 2D texture");
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t3, 0);
  err("glFramebufferTexture2D of a 3D texture");
  glFramebufferTexture3D(0x1234, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, t3, 0, 0);
  err("bad target");
  glFramebufferTexture3D(GL_FRAMEBUFFER, 0x1234, GL_TEXTURE_3D, t3, 0, 0);
  err("bad attachment");
  glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, 0, 0, 5);
  err("detach");
  printf("%-40s 0x%x\n", "status", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

static void quad(int col, int row, float r0, float r1) {
  float x0 = (float)(col * P), y0 = (float)(row * P), x1 = x0 + P, y1 = y0 + P;
  glBegin(GL_QUADS);
  glTexCoord3f(0, 0, r0); glVertex2f(x0, y0);
  glTexCoord3f(1, 0, r1); glVertex2f(x1, y0);
  glTexCoord3f(1, 1, r1); glVertex2f(x1, y1);
  glTexCoord3f(0, 1, r0); glVertex2f(x0, y1);
  glEnd();
}

static void filters(GLenum min, GLenum mag) {
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, min);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, mag);
}

static void panels(void) {
  glViewport(0, 0, W, H);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.1f, 0.2f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  GLuint tex[4];
  glGenTextures(4, tex);
  /* Row 0: the volume's four images by r, NEAREST; then LINEAR across r; wrap R. */
  glBindTexture(GL_TEXTURE_3D, tex[0]);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, volume);
  filters(GL_NEAREST, GL_NEAREST);
  glEnable(GL_TEXTURE_3D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (int z = 0; z < 4; z++) quad(z, 0, (2 * z + 1) / 8.0f, (2 * z + 1) / 8.0f);
  filters(GL_LINEAR, GL_LINEAR);
  quad(4, 0, 0, 1);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_REPEAT);
  quad(5, 0, 0.9f, 1.6f);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  quad(6, 0, 0.9f, 1.6f);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP);
  quad(7, 0, 0.5f, 1.0f);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_REPEAT);
  /* A 2D texture enabled too: TEXTURE_3D wins (row 1, panel 0). */
  glBindTexture(GL_TEXTURE_2D, tex[3]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, volume);
  glEnable(GL_TEXTURE_2D);
  quad(0, 1, 0.375f, 0.375f);
  glDisable(GL_TEXTURE_3D);
  quad(1, 1, 0.375f, 0.375f);
  glEnable(GL_TEXTURE_3D);
  glDisable(GL_TEXTURE_2D);
  /* Row 1, panels 2–3: glTexSubImage3D paints image 2's middle white, glCopyTexSubImage3D
   * copies row 0's first panel corner into image 1. */
  filters(GL_NEAREST, GL_NEAREST);
  static const GLubyte white[2 * 2 * 4] = {255, 255, 255, 255, 255, 255, 255, 255,
                                           255, 255, 255, 255, 255, 255, 255, 255};
  glTexSubImage3D(GL_TEXTURE_3D, 0, 1, 1, 2, 2, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
  quad(2, 1, 0.625f, 0.625f);
  glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 1, 2, 2, 4, 4);
  quad(3, 1, 0.375f, 0.375f);
  /* Row 1, panels 4–5: a mipmapped volume (levels of one colour each) minified 6×, and
   * GENERATE_MIPMAP from a checkered base. */
  glBindTexture(GL_TEXTURE_3D, tex[1]);
  static const GLubyte colours[4][4] = {
      {250, 30, 30, 255}, {30, 250, 30, 255}, {30, 30, 250, 255}, {200, 200, 200, 255}};
  const int sizes[4][3] = {{8, 8, 4}, {4, 4, 2}, {2, 2, 1}, {1, 1, 1}};
  for (int l = 0; l < 4; l++) {
    int n = sizes[l][0] * sizes[l][1] * sizes[l][2];
    for (int i = 0; i < n; i++) memcpy(scratch + 4 * i, colours[l], 4);
    glTexImage3D(GL_TEXTURE_3D, l, GL_RGBA8, sizes[l][0], sizes[l][1], sizes[l][2], 0,
                 GL_RGBA, GL_UNSIGNED_BYTE, scratch);
  }
  filters(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
  glBegin(GL_QUADS);
  glTexCoord3f(0, 0, 0.5f); glVertex2i(4 * P, P);
  glTexCoord3f(6, 0, 0.5f); glVertex2i(5 * P, P);
  glTexCoord3f(6, 6, 0.5f); glVertex2i(5 * P, 2 * P);
  glTexCoord3f(0, 6, 0.5f); glVertex2i(4 * P, 2 * P);
  glEnd();
  glBindTexture(GL_TEXTURE_3D, tex[2]);
  glTexParameteri(GL_TEXTURE_3D, GL_GENERATE_MIPMAP, GL_TRUE);
  for (int i = 0; i < 8 * 8 * 8; i++) {
    int x = i % 8, z = i / 64;
    GLubyte c = (x + z) % 2 ? 255 : 0;
    scratch[4 * i] = c;
    scratch[4 * i + 1] = c;
    scratch[4 * i + 2] = 128;
    scratch[4 * i + 3] = 255;
  }
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, scratch);
  filters(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
  glBegin(GL_QUADS);
  glTexCoord3f(0, 0, 0.3f); glVertex2i(5 * P, P);
  glTexCoord3f(4, 0, 0.3f); glVertex2i(6 * P, P);
  glTexCoord3f(4, 4, 0.3f); glVertex2i(6 * P, 2 * P);
  glTexCoord3f(0, 4, 0.3f); glVertex2i(5 * P, 2 * P);
  glEnd();
  /* Row 1, panels 6–7: a LUMINANCE volume with MODULATE, LINEAR across r; image 1 of a
   * volume cleared through a framebuffer object. */
  GLuint lum;
  glGenTextures(1, &lum);
  glBindTexture(GL_TEXTURE_3D, lum);
  static const GLubyte l8[8] = {30, 90, 150, 210, 250, 200, 100, 50};
  glTexImage3D(GL_TEXTURE_3D, 0, GL_LUMINANCE8, 2, 2, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, l8);
  filters(GL_LINEAR, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor4f(1, 0.5f, 0.25f, 1);
  quad(6, 1, 0, 1);
  glColor4f(1, 1, 1, 1);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  GLuint fb, target;
  glGenFramebuffers(1, &fb);
  glGenTextures(1, &target);
  glBindTexture(GL_TEXTURE_3D, target);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 4, 4, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  filters(GL_NEAREST, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, target, 0, 1);
  glClearColor(0.8f, 0.4f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  quad(7, 1, 0.5f, 0.5f);
  /* Rows 2–3: r from texgen OBJECT_LINEAR (r = x/64 over the object) on a perspective
   * quad, LINEAR, REPEAT in r; and the same through a texture matrix that scales r. */
  glBindTexture(GL_TEXTURE_3D, tex[0]);
  filters(GL_LINEAR, GL_LINEAR);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -0.25, 0.25, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glViewport(0, 2 * P, W, 2 * P);
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  static const GLfloat plane[4] = {0.5f, 0, 0, 0.5f};
  glTexGenfv(GL_R, GL_OBJECT_PLANE, plane);
  glEnable(GL_TEXTURE_GEN_R);
  for (int k = 0; k < 2; k++) {
    float x0 = k ? 0.05f : -1.9f, x1 = k ? 1.9f : -0.05f;
    if (k) {
      glMatrixMode(GL_TEXTURE);
      glScalef(1, 1, 2.5f);
      glMatrixMode(GL_MODELVIEW);
    }
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex3f(x0, -0.4f, -1.5f);
    glTexCoord2f(1, 0); glVertex3f(x1, -0.4f, -1.5f);
    glTexCoord2f(1, 1); glVertex3f(x1, 0.4f, -3.5f);
    glTexCoord2f(0, 1); glVertex3f(x0, 0.4f, -3.5f);
    glEnd();
  }
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glDisable(GL_TEXTURE_GEN_R);
  glDisable(GL_TEXTURE_3D);
}

int main(int argc, char **argv) {
  const char *path = argc > 1 ? argv[1] : "tex3d.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  fill_volume();
  errors_and_queries();
  framebuffer_3d();
  panels();
  glFinish();
  if (!write_ppm(path, buf, W, H)) return 1;
  OSMesaDestroyContext(ctx);
  free(buf);
  return 0;
}
