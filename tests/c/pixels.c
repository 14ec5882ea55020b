/* The raster position and pixel rectangles through the C library: six panels — a
 * glDrawPixels image at GL_UNPACK_ALIGNMENT 4 with rows of 57 bytes, the same image flipped by
 * glPixelZoom(2, -2) with a red scale, a line of glBitmap glyphs moving the raster
 * position (and the glBitmap(0, 0, 0, 0, dx, dy, NULL) idiom), a lit raster colour on a
 * bitmap, a depth image revealed by a depth-tested quad, a glCopyPixels of panel 0 — then
 * one line per query (glGet of the raster position, its validity, colour, texture
 * coordinates and distance, the zoom and the transfer state) and per error check.
 *
 * usage: pixels OUT.ppm */
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

static void floats(const char *name, GLenum pname, int n) {
  GLfloat v[4] = {0, 0, 0, 0};
  glGetFloatv(pname, v);
  printf("%-32s", name);
  for (int i = 0; i < n; i++) printf(" %.4f", v[i]);
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

  /* A 19×12 RGB image: rows of 57 bytes, padded to 60 under the default alignment 4. */
  static GLubyte image[12][60];
  for (int y = 0; y < 12; y++)
    for (int x = 0; x < 19; x++) {
      image[y][3 * x] = (GLubyte)(x * 13);
      image[y][3 * x + 1] = (GLubyte)(y * 21);
      image[y][3 * x + 2] = (GLubyte)((x + y) % 2 ? 255 : 40);
    }
  image[0][0] = image[0][1] = image[0][2] = 255;

  /* 0: the image at (5, 5), unzoomed. */
  panel(0);
  glRasterPos2i(5, 5);
  glDrawPixels(19, 12, GL_RGB, GL_UNSIGNED_BYTE, image);
  report("glDrawPixels RGB, alignment 4");

  /* 1: flipped and doubled, red halved. */
  panel(1);
  glRasterPos2f(10.25f, 50.5f);
  glPixelZoom(2, -2);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glDrawPixels(19, 12, GL_RGB, GL_UNSIGNED_BYTE, image);
  floats("GL_ZOOM_X, GL_ZOOM_Y", GL_ZOOM_X, 1);
  floats("GL_RED_SCALE", GL_RED_SCALE, 1);
  glPixelTransferf(GL_RED_SCALE, 1);
  glPixelZoom(1, 1);
  report("glPixelZoom and glPixelTransferf");

  /* 2: glyphs of 10×10 bits (2 bytes a row), advancing by 11, then the NULL idiom. */
  panel(2);
  static const GLubyte glyph[10][2] = {{0xff, 0xc0}, {0xff, 0xc0}, {0xf3, 0xc0}, {0xe1, 0xc0},
                                       {0xc0, 0xc0}, {0xc0, 0xc0}, {0xe1, 0xc0}, {0xf3, 0xc0},
                                       {0xff, 0xc0}, {0xff, 0xc0}};
  glColor3f(1, 0.75f, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1); /* rows of 2 bytes, unpadded */
  glRasterPos2i(2, 40);
  for (int i = 0; i < 5; i++) glBitmap(10, 10, 0, 0, 11, 0, &glyph[0][0]);
  floats("raster position after 5 glyphs", GL_CURRENT_RASTER_POSITION, 4);
  glBitmap(0, 0, 0, 0, -44, -20, NULL);
  glBitmap(10, 10, 0, 0, 0, 0, &glyph[0][0]);
  floats("raster position after the move", GL_CURRENT_RASTER_POSITION, 4);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  report("glBitmap");

  /* 3: a lit raster colour, drawn by a bitmap. */
  panel(3);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  GLfloat diffuse[4] = {0.2f, 0.6f, 1.0f, 1.0f};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glNormal3f(0, 0.6f, 0.8f);
  glRasterPos2i(20, 20);
  glDisable(GL_LIGHTING);
  floats("lit GL_CURRENT_RASTER_COLOR", GL_CURRENT_RASTER_COLOR, 4);
  static GLubyte square[32][4];
  memset(square, 0xff, sizeof square);
  glBitmap(32, 32, 0, 0, 0, 0, &square[0][0]);
  report("lit raster position");

  /* 4: a depth ramp, revealed by a quad at depth 0.5 drawn with LESS. */
  panel(4);
  static GLfloat depths[16 * 16];
  for (int i = 0; i < 16 * 16; i++) depths[i] = (i % 16) / 15.0f;
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glRasterPos2i(10, 10);
  glDrawPixels(16, 16, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  glDepthFunc(GL_LESS);
  glColor3f(1, 0, 0);
  glBegin(GL_QUADS);
  glVertex3f(0, 0, 0);
  glVertex3f(64, 0, 0);
  glVertex3f(64, 64, 0);
  glVertex3f(0, 64, 0);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  report("glDrawPixels DEPTH_COMPONENT");

  /* 5: panel 0's image copied with glCopyPixels (window coordinates). */
  panel(5);
  glWindowPos2i(128 + 20, 64 + 20);
  glCopyPixels(5, 5, 19, 12, GL_COLOR);
  report("glCopyPixels COLOR");

  /* Queries. */
  glColor4f(0.25f, 0.5f, 0.75f, 1);
  glMultiTexCoord4f(GL_TEXTURE1, 0.5f, 0.25f, 0, 1);
  glActiveTexture(GL_TEXTURE1);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRasterPos3f(0.5f, -0.25f, -3);
  floats("GL_CURRENT_RASTER_POSITION", GL_CURRENT_RASTER_POSITION, 4);
  floats("GL_CURRENT_RASTER_COLOR", GL_CURRENT_RASTER_COLOR, 4);
  floats("GL_CURRENT_RASTER_TEXTURE_COORDS", GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
  floats("GL_CURRENT_RASTER_DISTANCE", GL_CURRENT_RASTER_DISTANCE, 1);
  GLboolean valid = 0;
  glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  printf("valid in view: %d\n", valid);
  glPushAttrib(GL_CURRENT_BIT);
  glRasterPos3f(0, 0, 5);
  glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  printf("valid behind the eye: %d\n", valid);
  glPopAttrib();
  glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  printf("valid after glPopAttrib: %d\n", valid);
  glRasterPos2sv((const GLshort[]){1, 2});
  glRasterPos4dv((const GLdouble[]){0.1, 0.2, -2, 1});
  glWindowPos3fv((const GLfloat[]){3, 4, 0.5f});
  floats("after glWindowPos3fv", GL_CURRENT_RASTER_POSITION, 4);
  glPixelTransferi(GL_INDEX_SHIFT, 3);
  GLint shift = 0;
  glGetIntegerv(GL_INDEX_SHIFT, &shift);
  printf("GL_INDEX_SHIFT %d\n", shift);
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  report("queries");

  /* Errors. */
  glDrawPixels(-1, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
  report("glDrawPixels negative width");
  glDrawPixels(1, 1, GL_RGBA, GL_BITMAP + 100, image);
  report("glDrawPixels bad type");
  glDrawPixels(1, 1, GL_RGBA + 100, GL_UNSIGNED_BYTE, image);
  report("glDrawPixels bad format");
  glBitmap(-1, 2, 0, 0, 0, 0, &glyph[0][0]);
  report("glBitmap negative height");
  glCopyPixels(0, 0, 2, 2, GL_RGBA);
  report("glCopyPixels bad type");
  glCopyPixels(0, 0, -2, 2, GL_COLOR);
  report("glCopyPixels negative width");
  glPixelTransferf(GL_TEXTURE_2D, 1);
  report("glPixelTransferf bad pname");
  glBegin(GL_POINTS);
  glRasterPos2i(1, 1);
  glEnd();
  report("glRasterPos inside glBegin");
  glBegin(GL_POINTS);
  glDrawPixels(1, 1, GL_RGB, GL_UNSIGNED_BYTE, image);
  glEnd();
  report("glDrawPixels inside glBegin");

  glFinish();
  if (!write_ppm(argv[1], buffer, W, H)) return 1;
  OSMesaDestroyContext(ctx);
  return 0;
}
