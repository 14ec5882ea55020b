/* Which pixels a line lights where its ends lie exactly on pixel centres or corners, as
 * Mesa's OSMesa shows them: GL's diamond-exit rule (GL 1.5 §3.4.1) leaves such ties to the
 * implementation, and llvmpipe breaks them by the orientation of the buffer in memory
 * (OSMesa's is a window-system buffer, rasterised upside down). Each case clears, draws one
 * line (or loop, or strip) in a 64x64 window with glOrtho(0,64,0,64), and prints the lit
 * pixels as a count and an FNV-1a hash of their indices:
 *   - vertical and horizontal lines both ways, and a diagonal, at x or y = 10.5 (centre),
 *     10 (corner), 10.25 and 10.75;
 *   - a line loop and a line strip through centres;
 *   - 200 pseudo-random lines with both ends on pixel centres, 200 on corners, at widths
 *     1, 2 and 3;
 *   - smooth (antialiased) points of size 1 and 2 on centres and corners, whose coverage
 *     ties the same way.
 * The last case's image is written to the output.
 *
 * usage: line_ends [out.ppm] */
#include <GL/osmesa.h>
#include <stdio.h>
#include "report.h"

#define W 64
#define H 64

static GLubyte *buf;

static void clear(void) { glClear(GL_COLOR_BUFFER_BIT); }

/* The lit pixels of the image so far: count and hash, after the name. */
static void lit(const char *what) {
  glFinish();
  unsigned long h = 1469598103934665603UL;
  int n = 0;
  for (int i = 0; i < W * H; i++)
    if (buf[4 * i]) {
      n++;
      h = (h ^ (unsigned long)i) * 1099511628211UL;
    }
  printf("%-32s lit %4d  hash %016lx  err 0x%x\n", what, n, h, glGetError());
}

static void line(GLenum mode, const GLfloat *xy, int n) {
  glBegin(mode);
  for (int i = 0; i < n; i++) glVertex2f(xy[2 * i], xy[2 * i + 1]);
  glEnd();
}

static unsigned seed = 12345;
static float rnd(void) {
  seed = seed * 1103515245u + 12345u;
  return (float)((seed >> 8) & 0xffff) / 65536.0f;
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "line_ends.ppm";
  OSMesaContext ctx;
  buf = open_window(&ctx, W, H);
  if (!buf) return 2;
  glColor3f(1, 1, 1);

  const GLfloat at[] = {10.5f, 10.0f, 10.25f, 10.75f};
  char name[64];
  for (int i = 0; i < 4; i++) {
    const GLfloat a = at[i];
    const GLfloat cases[5][4] = {{a, 50.5f, a, 40.5f},
                                 {a, 40.5f, a, 50.5f},
                                 {40.5f, a, 50.5f, a},
                                 {50.5f, a, 40.5f, a},
                                 {30 + a, 40.5f, 40 + a, 50.5f}};
    const char *names[5] = {"down", "up", "right", "left", "diagonal"};
    for (int k = 0; k < 5; k++) {
      clear();
      line(GL_LINES, cases[k], 2);
      snprintf(name, sizeof name, "%s at %g", names[k], a);
      lit(name);
    }
  }
  const GLfloat triangle[] = {10.5f, 10.5f, 50.5f, 10.5f, 10.5f, 50.5f};
  clear();
  line(GL_LINE_LOOP, triangle, 3);
  lit("loop through centres");
  clear();
  line(GL_LINE_STRIP, triangle, 3);
  lit("strip through centres");

  for (int width = 1; width <= 3; width++) {
    glLineWidth((GLfloat)width);
    for (int corner = 0; corner <= 1; corner++) {
      unsigned long all = 1469598103934665603UL;
      int total = 0;
      for (int i = 0; i < 200; i++) {
        GLfloat xy[4];
        for (int k = 0; k < 4; k++) xy[k] = (GLfloat)(int)(8 + rnd() * 48) + (corner ? 0.0f : 0.5f);
        clear();
        line(GL_LINES, xy, 2);
        glFinish();
        for (int p = 0; p < W * H; p++)
          if (buf[4 * p]) {
            total++;
            all = (all ^ (unsigned long)(p + 4096 * i)) * 1099511628211UL;
          }
      }
      printf("random on %-7s width %d      lit %5d  hash %016lx  err 0x%x\n",
             corner ? "corners" : "centres", width, total, all, glGetError());
    }
  }
  glLineWidth(1);

  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int size = 1; size <= 2; size++) {
    glPointSize((GLfloat)size);
    clear();
    glBegin(GL_POINTS);
    for (int i = 0; i < 8; i++) {
      glVertex2f(6.5f + 7 * i, 20.5f);
      glVertex2f(6.0f + 7 * i, 40.0f);
    }
    glEnd();
    snprintf(name, sizeof name, "smooth points size %d", size);
    lit(name);
  }
  return finish(out, ctx, buf, W, H);
}
