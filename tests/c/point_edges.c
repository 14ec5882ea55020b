/* Aliased points where llvmpipe's rule for legacy points decides which pixels they cover:
 * centres at every 1/512 of a pixel across two pixels, for sides 1 to 6 (odd sides put a
 * square's edges on pixel centres); points whose centre lies on the right or top plane of
 * a viewport smaller than the buffer (inside the view volume, drawn beyond the viewport);
 * points a polygon in POINT mode makes, at its corners and where clipping cuts it; the
 * same under distance attenuation. Each panel prints how many pixels it lit. Run on Mesa's
 * OSMesa and on fixedfunc's library, the printed lines must be the same and the images
 * the same pixel for pixel.
 *
 * usage: point_edges [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"

#define W 256
#define H 256

static GLubyte *image;

/* Pixels of the box (x, y, w, h) whose red is set. */
static int lit(int x, int y, int w, int h) {
  glFinish();
  int n = 0;
  for (int j = y; j < y + h; j++)
    for (int i = x; i < x + w; i++)
      if (i >= 0 && j >= 0 && i < W && j < H && image[4 * (j * W + i)]) n++;
  return n;
}

/* Sizes 1..6 in rows at `y`; in each, 32 points whose centres step by 1/512 pixel in x and
 * 3/512 in y from `from` (a pixel edge, 0, or a pixel centre, 0.5), minus 16/512, each in
 * its own 8×8 cell. */
static void subpixel_rows(int y, float from) {
  glViewport(0, 0, W, H);
  for (int s = 1; s <= 6; s++) {
    glPointSize((float)s);
    glBegin(GL_POINTS);
    for (int i = 0; i < 32; i++) {
      float d = (float)(i - 16) / 512.0f;
      glColor3f(1, (float)s / 6.0f, (float)i / 32.0f);
      glVertex2f(4.0f + from + 8.0f * (float)i + d, (float)y + 4.0f + from + 8.0f * (float)(s - 1) + 3.0f * d);
    }
    glEnd();
    printf("side %d from %.1f at 1/512 steps lit %d\n", s, from, lit(0, y + 8 * (s - 1), W, 8));
  }
}

/* A 24×24 viewport at (x, y) without a scissor; points of sides 1..5 at its right and top
 * planes (x_w = x + 24 or y_w = y + 24) and a thousandth inside them. */
static void on_the_planes(int x, int y, int attenuated) {
  glViewport(x, y, 24, 24);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 24, 0, 24, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  if (attenuated) {
    GLfloat att[3] = {0.25f, 0.0f, 0.0f};
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
  }
  for (int s = 1; s <= 5; s++) {
    glPointSize(attenuated ? 0.5f * (float)s : (float)s);
    glBegin(GL_POINTS);
    glColor3f(1, 1, 1);
    glVertex2f(24.0f, 2.0f + 4.4f * (float)(s - 1));
    glVertex2f(23.999f, 2.5f + 4.4f * (float)(s - 1));
    glVertex2f(2.0f + 4.4f * (float)(s - 1), 24.0f);
    glVertex2f(2.5f + 4.4f * (float)(s - 1), 23.999f);
    glEnd();
  }
  GLfloat none[3] = {1, 0, 0};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
  printf("planes at (%3d, %3d) attenuated %d lit %d\n", x, y, attenuated, lit(x, y, 32, 32));
}

/* Triangles in POINT mode: one cut by the near plane, one by the right plane of a 32×32
 * viewport, one inside with corners off the grid; sides 1 and 3. */
static void polygon_points(int x, int y, float side) {
  glViewport(x, y, 32, 32);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glPointSize(side);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0.5f, 0);
  glVertex3f(-0.8f, -0.8f, 0);
  glVertex3f(0.8f, -0.8f, 0);
  glVertex3f(0.0f, 0.8f, -3);
  glColor3f(1, 0, 1);
  glVertex3f(-0.5f, -0.3f, 0);
  glVertex3f(1.8f, -0.2f, 0);
  glVertex3f(0.0f, 0.6f, 0);
  glColor3f(1, 1, 0);
  glVertex3f(-0.9f, 0.2f, 0);
  glVertex3f(-0.3f, 0.3f, 0);
  glVertex3f(-0.6f, 0.9f, 0);
  glEnd();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  printf("polygon points side %.0f          lit %d\n", side, lit(x, y, 40, 40));
}

int main(int argc, char **argv) {
  OSMesaContext ctx;
  image = open_window(&ctx, W, H); /* a unit a pixel */
  if (!image) return 3;
  subpixel_rows(0, 0.0f);
  subpixel_rows(160, 0.5f);
  on_the_planes(8, 64, 0);
  on_the_planes(48, 64, 1);
  polygon_points(96, 64, 1);
  polygon_points(144, 64, 3);
  on_the_planes(8, 112, 0);
  polygon_points(200, 64, 2);
  printf("errors                          err 0x%x\n", glGetError());
  return finish(argc > 1 ? argv[1] : "point_edges.ppm", ctx, image, W, H);
}
