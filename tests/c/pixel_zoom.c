/* Zoomed pixel rectangles, where a pixel centre falls on the boundary between two of the
 * image's pixels (zoom 0.5, 1.5, 0.3 …) and the rasteriser's rounding decides which one it
 * shows. Eight 64×64 panels of the window: glDrawPixels of a 20×20 image whose pixels all
 * differ at zooms (0.5, 0.5), (1.5, 1.5), (0.3, 0.7), (−0.5, −1.5), (2.5, 0.25), and
 * glCopyPixels of the image drawn unzoomed in panel 4 at (0.75, 1.25), (0.5, −0.5) and (1.5, 0.5). Then a
 * framebuffer object larger than the window (320×160): the same image drawn at zoom
 * (1.5, 0.5) past the window's edges, copied at (0.5, 1.5), a depth image at (0.5, 1.5) and
 * a stencil image at (1.5, 0.75), each printed as a checksum of what glReadPixels reads.
 *
 * usage: pixel_zoom OUT.ppm */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>

#include "report.h"

#define W 256
#define H 128
#define FW 320
#define FH 160
#define N 20

static GLubyte image[N * N * 4];
static GLfloat depth[N * N];
static GLubyte stencil[N * N];

/* The raster position at window (x, y) under glOrtho(0, w, 0, h). */
static void raster_at(int x, int y) { glRasterPos2i(x, y); }

static void zoomed(int x, int y, float zx, float zy) {
  glPixelZoom(zx, zy);
  raster_at(x, y);
  glDrawPixels(N, N, GL_RGBA, GL_UNSIGNED_BYTE, image);
}

/* A copy of the unzoomed image at (sx, sy) to (x, y). */
static void copied(int sx, int sy, int x, int y, float zx, float zy) {
  glPixelZoom(zx, zy);
  raster_at(x, y);
  glCopyPixels(sx, sy, N, N, GL_COLOR);
}

/* FNV-1a of the bytes: one line per readback. */
static void checksum(const char *what, const void *data, size_t n) {
  const GLubyte *p = data;
  unsigned h = 2166136261u;
  for (size_t i = 0; i < n; i++) h = (h ^ p[i]) * 16777619u;
  printf("%-40s %08x err 0x%x\n", what, h, glGetError());
}

static void object_case(const char *what, GLenum format, GLenum type, size_t texel) {
  static GLubyte out[FW * FH * 4];
  glReadPixels(0, 0, FW, FH, format, type, out);
  checksum(what, out, (size_t)FW * FH * texel);
}

static void ortho(int w, int h) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, w, 0, h, -1, 1);
  glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char **argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s OUT.ppm\n", argv[0]);
    return 2;
  }
  OSMesaContext ctx;
  GLubyte *buf = open_window(&ctx, W, H);
  if (!buf) return 1;
  for (int j = 0; j < N; j++)
    for (int i = 0; i < N; i++) {
      GLubyte *p = image + 4 * (j * N + i);
      p[0] = (GLubyte)(i * 12);
      p[1] = (GLubyte)(j * 12);
      p[2] = (GLubyte)((i + j) % 2 ? 230 : 60);
      p[3] = 255;
      depth[j * N + i] = (GLfloat)(i + N * j) / (N * N);
      stencil[j * N + i] = (GLubyte)(i + N * j);
    }
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  zoomed(2, 3, 0.5f, 0.5f);
  zoomed(64 + 3, 5, 1.5f, 1.5f);
  zoomed(128 + 3, 5, 0.3f, 0.7f);
  zoomed(192 + 60, 60, -0.5f, -1.5f);
  zoomed(1, 64 + 3, 2.5f, 0.25f);
  glPixelZoom(1, 1);
  raster_at(20, 100);
  glDrawPixels(N, N, GL_RGBA, GL_UNSIGNED_BYTE, image);
  copied(20, 100, 64 + 2, 64 + 3, 0.75f, 1.25f);
  copied(20, 100, 128 + 2, 64 + 30, 0.5f, -0.5f);
  copied(20, 100, 192 + 2, 64 + 3, 1.5f, 0.5f);
  err("window rectangles");

  GLuint fb, rb[2];
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glGenRenderbuffers(2, rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, FW, FH);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
  glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, FW, FH);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
  printf("%-40s 0x%x\n", "object status", glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glViewport(0, 0, FW, FH);
  ortho(FW, FH);
  glClearColor(0, 0, 0, 0);
  glClearDepth(1);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  zoomed(250, 120, 1.5f, 0.5f);
  object_case("object: drawn past the window", GL_RGBA, GL_UNSIGNED_BYTE, 4);
  glPixelZoom(1, 1);
  raster_at(2, 3);
  glDrawPixels(N, N, GL_RGBA, GL_UNSIGNED_BYTE, image);
  copied(2, 3, 270, 100, 0.5f, 1.5f);
  object_case("object: copied past the window", GL_RGBA, GL_UNSIGNED_BYTE, 4);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glPixelZoom(0.5f, 1.5f);
  raster_at(280, 110);
  glDrawPixels(N, N, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  glDisable(GL_DEPTH_TEST);
  object_case("object: depth image", GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, 2);
  glPixelZoom(1.5f, 0.75f);
  raster_at(270, 140);
  glDrawPixels(N, N, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
  object_case("object: stencil image", GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return finish(argv[1], ctx, buf, W, H);
}
