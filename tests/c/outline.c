/* Stippled outlines: polygons in LINE mode while LINE_STIPPLE is on, as CAD and
 * hidden-line programs draw them — every polygon primitive type, smooth and flat, edge
 * flags, culling and separate front and back modes, wide lines, a filled pass under them
 * with polygon offset. Each panel prints how many pixels it lit. Run on Mesa's OSMesa and
 * on fixedfunc's library, the printed lines must be the same and the images match.
 *
 * usage: outline [out.ppm] */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 128
#define H 96
static GLubyte *buf;

/* Panel k of a 4 x 3 grid of 32 x 32 pixels. */
static void panel(int k) { glViewport((k % 4) * 32, (k / 4) * 32, 32, 32); }

static int lit(int k) {
  glFinish();
  int n = 0;
  for (int y = (k / 4) * 32; y < (k / 4) * 32 + 32; y++)
    for (int x = (k % 4) * 32; x < (k % 4) * 32 + 32; x++)
      if (buf[4 * (y * W + x)] | buf[4 * (y * W + x) + 1] | buf[4 * (y * W + x) + 2]) n++;
  return n;
}

static void colour(int i) {
  glColor3f((float)(i % 3 == 0), (float)(i % 3 == 1) * 0.8f + 0.2f, (float)(i % 2));
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "outline.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glClear(GL_COLOR_BUFFER_BIT);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x0F3F);
  err("line mode with stipple");

  /* 0: independent triangles. */
  panel(0);
  glBegin(GL_TRIANGLES);
  colour(0); glVertex2f(-0.9f, -0.9f); colour(1); glVertex2f(0.8f, -0.7f); colour(2); glVertex2f(-0.6f, 0.1f);
  colour(3); glVertex2f(0.9f, -0.2f); colour(4); glVertex2f(0.7f, 0.9f); colour(5); glVertex2f(-0.8f, 0.6f);
  glEnd();
  printf("triangles %d\n", lit(0));
  /* 1: a triangle strip. */
  panel(1);
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 6; i++) {
    colour(i);
    glVertex2f(-0.85f + 0.33f * (float)i, (i & 1) ? 0.7f : -0.6f);
  }
  glEnd();
  printf("triangle strip %d\n", lit(1));
  /* 2: a triangle fan. */
  panel(2);
  glBegin(GL_TRIANGLE_FAN);
  colour(0); glVertex2f(-0.8f, -0.8f);
  for (int i = 0; i < 5; i++) {
    colour(i + 1);
    glVertex2f(0.9f - 0.35f * (float)i, -0.8f + 0.4f * (float)i);
  }
  glEnd();
  printf("triangle fan %d\n", lit(2));
  /* 3: quads, the pattern stretched. */
  panel(3);
  glLineStipple(2, 0x0F3F);
  glBegin(GL_QUADS);
  colour(0); glVertex2f(-0.9f, -0.9f); colour(1); glVertex2f(-0.1f, -0.8f);
  colour(2); glVertex2f(-0.2f, -0.1f); colour(3); glVertex2f(-0.85f, -0.2f);
  colour(4); glVertex2f(0.1f, 0.1f); colour(5); glVertex2f(0.9f, 0.2f);
  colour(6); glVertex2f(0.8f, 0.9f); colour(7); glVertex2f(0.2f, 0.8f);
  glEnd();
  printf("quads %d\n", lit(3));
  glLineStipple(1, 0x0F3F);
  /* 4: a quad strip. */
  panel(4);
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i < 8; i++) {
    colour(i);
    glVertex2f(-0.9f + 0.25f * (float)(i / 2), (i & 1) ? 0.8f : -0.7f + 0.1f * (float)(i / 2));
  }
  glEnd();
  printf("quad strip %d\n", lit(4));
  /* 5: a polygon. */
  panel(5);
  glBegin(GL_POLYGON);
  colour(0); glVertex2f(0, -0.9f); colour(1); glVertex2f(0.8f, -0.4f); colour(2); glVertex2f(0.7f, 0.6f);
  colour(3); glVertex2f(-0.1f, 0.9f); colour(4); glVertex2f(-0.8f, 0.3f); colour(5); glVertex2f(-0.7f, -0.6f);
  glEnd();
  printf("polygon %d\n", lit(5));
  /* 6: flat shading: each outline in its polygon's colour. */
  panel(6);
  glShadeModel(GL_FLAT);
  glBegin(GL_QUADS);
  colour(0); glVertex2f(-0.9f, -0.9f); colour(1); glVertex2f(0.9f, -0.9f);
  colour(2); glVertex2f(0.9f, -0.1f); colour(3); glVertex2f(-0.9f, -0.1f);
  glEnd();
  glBegin(GL_POLYGON);
  colour(4); glVertex2f(-0.9f, 0.1f); colour(5); glVertex2f(0.9f, 0.1f); colour(6); glVertex2f(0, 0.9f);
  glEnd();
  glShadeModel(GL_SMOOTH);
  printf("flat %d\n", lit(6));
  /* 7: edge flags hide the edges from the flagged vertices. */
  panel(7);
  glColor3f(1, 1, 0);
  glBegin(GL_POLYGON);
  glVertex2f(-0.9f, -0.9f); glEdgeFlag(GL_FALSE); glVertex2f(0.9f, -0.9f); glEdgeFlag(GL_TRUE);
  glVertex2f(0.9f, 0.9f); glVertex2f(-0.9f, 0.9f);
  glEnd();
  printf("edge flags %d\n", lit(7));
  /* 8: front faces in LINE, back faces filled, one of each. */
  panel(8);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_FILL);
  glBegin(GL_TRIANGLES);
  glColor3f(0, 1, 1);
  glVertex2f(-0.9f, -0.9f); glVertex2f(0.8f, -0.9f); glVertex2f(-0.9f, 0.8f);
  glColor3f(0.5f, 0, 0.5f);
  glVertex2f(0.9f, 0.9f); glVertex2f(0.9f, -0.5f); glVertex2f(-0.5f, 0.9f);
  glEnd();
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  printf("front line back fill %d\n", lit(8));
  /* 9: back faces culled. */
  panel(9);
  glEnable(GL_CULL_FACE);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0.5f, 0);
  glVertex2f(-0.9f, -0.9f); glVertex2f(0.8f, -0.9f); glVertex2f(-0.9f, 0.8f);
  glVertex2f(0.9f, 0.9f); glVertex2f(0.9f, -0.5f); glVertex2f(-0.5f, 0.9f);
  glEnd();
  glDisable(GL_CULL_FACE);
  printf("culled %d\n", lit(9));
  /* 10: wide stippled outlines. */
  panel(10);
  glLineWidth(3);
  glColor3f(0.6f, 0.9f, 0.3f);
  glBegin(GL_QUADS);
  glVertex2f(-0.7f, -0.7f); glVertex2f(0.7f, -0.6f); glVertex2f(0.6f, 0.7f); glVertex2f(-0.6f, 0.6f);
  glEnd();
  glLineWidth(1);
  printf("wide %d\n", lit(10));
  /* 11: hidden lines: a filled pass pushed back by polygon offset, then dashed outlines. */
  panel(11);
  glEnable(GL_DEPTH_TEST);
  glClear(GL_DEPTH_BUFFER_BIT);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1, 1);
  glColor3f(0.15f, 0.15f, 0.3f);
  for (int pass = 0; pass < 2; pass++) {
    glBegin(GL_QUADS);
    glVertex3f(-0.8f, -0.8f, 0.2f); glVertex3f(0.5f, -0.8f, 0.2f); glVertex3f(0.5f, 0.5f, 0.2f); glVertex3f(-0.8f, 0.5f, 0.2f);
    glVertex3f(-0.4f, -0.4f, -0.2f); glVertex3f(0.9f, -0.4f, -0.2f); glVertex3f(0.9f, 0.9f, -0.2f); glVertex3f(-0.4f, 0.9f, -0.2f);
    glEnd();
    glDisable(GL_POLYGON_OFFSET_FILL);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(1, 1, 1);
  }
  glDisable(GL_DEPTH_TEST);
  printf("hidden lines %d\n", lit(11));
  glViewport(0, 0, W, H);
  err("after the panels");
  glFinish();
  if (!write_ppm(out, buf, W, H)) return 1;
  OSMesaDestroyContext(ctx);
  free(buf);
  return 0;
}
