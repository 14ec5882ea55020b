/* The pixel transfer on texture images and reads, and texture images whose client format
 * differs from their internal format: glPixelTransfer's scales and biases and MAP_COLOR's
 * maps on glTexImage2D, glTexSubImage2D, glCopyTexImage2D, glCopyTexSubImage2D and
 * glReadPixels (the maps by the nearest entry there, where glDrawPixels truncates), none on
 * glGetTexImage nor on depth images; ALPHA data into RGBA, LUMINANCE_ALPHA into ALPHA and
 * LUMINANCE, RGB into LUMINANCE_ALPHA, the framebuffer copied into ALPHA and
 * LUMINANCE_ALPHA textures. Each texture is read back with glGetTexImage and drawn into a
 * panel. Run on Mesa's OSMesa and on fixedfunc's library, the printed lines must be the
 * same and the images match.
 *
 * usage: transfer [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 64
#define H 32
static GLubyte *buf;
static int panels;

/* The bound texture's level 0 as RGBA bytes, and a panel drawn with it (REPLACE). */
static void show(const char *what) {
  GLubyte t[4 * 4] = {0};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  printf("%-34s %d %d %d %d err %x\n", what, t[0], t[1], t[2], t[3], glGetError());
  glViewport((panels % 8) * 8, 8 + (panels / 8) * 8, 8, 8);
  panels++;
  glEnable(GL_TEXTURE_2D);
  glRectf(-1, -1, 1, 1);
  glDisable(GL_TEXTURE_2D);
  glViewport(0, 0, W, H);
}

static void read1(const char *what, int x, int y) {
  GLubyte r[4];
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, r);
  printf("%-34s %d %d %d %d err %x\n", what, r[0], r[1], r[2], r[3], glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "transfer.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  GLuint tex = replace_texture_panels();

  /* Scale and bias on glTexImage2D, then on glReadPixels of the texture drawn. */
  GLubyte grey[4] = {200, 200, 200, 255};
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_BIAS, 0.1f);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, grey);
  glPixelTransferf(GL_RED_SCALE, 1);
  glPixelTransferf(GL_GREEN_BIAS, 0);
  show("teximage scaled and biased");
  glPixelTransferf(GL_BLUE_SCALE, 0.25f);
  read1("readpixels scaled", 3, 11);
  glPixelTransferf(GL_BLUE_SCALE, 2);
  show("getteximage takes no transfer");
  glPixelTransferf(GL_BLUE_SCALE, 1);

  /* MAP_COLOR by the nearest entry on images read and texture images. */
  GLfloat map[5] = {0, 0.25f, 0.5f, 0.75f, 1};
  GLfloat one = 1;
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 5, map);
  glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 5, map);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 5, map);
  glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 1, &one);
  GLubyte c[4] = {51, 128, 160, 255};
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, c);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  show("teximage mapped");
  glClearColor(51 / 255.0f, 0.5f, 0.625f, 1);
  glScissor(0, 0, 8, 8);
  glEnable(GL_SCISSOR_TEST);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  read1("readpixels mapped", 2, 2);
  {
    GLfloat f[4];
    glReadPixels(2, 2, 1, 1, GL_LUMINANCE, GL_FLOAT, f);
    printf("readpixels mapped luminance %g err %x\n", f[0], glGetError());
  }
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 1, 1, 0);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  show("copyteximage mapped");
  glPixelTransferf(GL_GREEN_SCALE, 0.5f);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, 1, 1);
  glPixelTransferf(GL_GREEN_SCALE, 1);
  show("copytexsubimage scaled");
  glPixelTransferf(GL_ALPHA_BIAS, -0.5f);
  GLubyte sub[4] = {10, 250, 90, 255};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, sub);
  glPixelTransferf(GL_ALPHA_BIAS, 0);
  show("texsubimage biased alpha");
  {
    GLfloat f[4];
    glPixelTransferf(GL_RED_SCALE, 2);
    glReadPixels(2, 2, 1, 1, GL_LUMINANCE, GL_FLOAT, f);
    glPixelTransferf(GL_RED_SCALE, 1);
    printf("readpixels scaled luminance float %g err %x\n", f[0], glGetError());
  }

  /* Depth images take no DEPTH_SCALE nor DEPTH_BIAS on Mesa. */
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.25f);
  GLfloat depth = 0.5f;
  GLuint dt;
  glGenTextures(1, &dt);
  glBindTexture(GL_TEXTURE_2D, dt);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  glPixelTransferf(GL_DEPTH_SCALE, 1);
  glPixelTransferf(GL_DEPTH_BIAS, 0);
  {
    GLfloat d = -1;
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
    printf("depth teximage %g err %x\n", d, glGetError());
  }
  glBindTexture(GL_TEXTURE_2D, tex);

  /* Client formats other than the internal one. */
  GLubyte a[1] = {100};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_ALPHA, GL_UNSIGNED_BYTE, a);
  show("alpha into rgba");
  GLubyte la[2] = {100, 200};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 1, 1, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
  show("luminance alpha into alpha");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 1, 1, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
  show("luminance alpha into luminance");
  GLubyte rgb[3] = {10, 20, 30};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  show("rgb into luminance alpha");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 1, 1, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, a);
  show("luminance into luminance alpha");
  GLubyte rgba[4] = {30, 60, 90, 120};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_INTENSITY, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  show("rgba into intensity");
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 1, 0, GL_ALPHA, GL_UNSIGNED_BYTE, a);
  show("alpha into rgb");

  /* The framebuffer copied into ALPHA and LUMINANCE_ALPHA textures. */
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glScissor(0, 0, 8, 8);
  glEnable(GL_SCISSOR_TEST);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 1, 1, 1, 1, 0);
  show("copy into alpha");
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 1, 1, 1, 1, 0);
  show("copy into luminance alpha");
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 1, 1, 1, 1, 0);
  show("copy into luminance");

  return finish(out, ctx, buf, W, H);
}
