/* The matrix commands' arithmetic, to the bit: glRotatef about every kind of axis (the
 * axis-aligned ones fill a 2×2 block, the others follow Mesa's formula term by term) and
 * by angles of every size, glTranslate and glScale in place (a scale by a negative number
 * leaves −0 in the bottom row), chains through the double variants, glFrustum, glOrtho,
 * glMultMatrix and glMultTransposeMatrix, and non-finite values: a rotation about a NaN or
 * infinite axis, by a NaN angle onto an affine matrix (the bottom row stays (0, 0, 0, 1))
 * and onto one that a glLoadMatrix, glMultMatrix or glFrustum made general (even after
 * glLoadIdentity: Mesa's type flags only gather). Each matrix is printed as hex floats, a
 * NaN as "nan" whatever its sign bit. Then a quad drawn under a general-axis rotation.
 *
 * usage: matrices [out.ppm] */
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "report.h"

#define W 64
#define H 64

static void print_matrix(const char *what, GLenum which) {
  GLfloat m[16];
  glGetFloatv(which, m);
  printf("%-28s", what);
  for (int i = 0; i < 16; i++) {
    if (isnan(m[i]))
      printf(" nan");
    else
      printf(" %a", m[i]);
  }
  printf("\n");
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "matrices.ppm";
  OSMesaContext ctx;
  GLubyte *buf = open_window(&ctx, W, H);
  if (!buf) return 2;
  static const float angles[] = {30, 45, 90, 180, 270, 360, 1e-3f, 123.456f, -77.7f, 720.5f};
  static const float axes[][3] = {{1, 0, 0},  {0, 1, 0},     {0, 0, 1},     {1, 1, 0},
                                  {0.3f, -0.5f, 2}, {0, 0, -1}, {1e-20f, 0, 0}, {0, 0, 0},
                                  {-2, 3, 0.5f}, {1e-5f, 1e-5f, 1e-5f}};
  char name[64];
  glMatrixMode(GL_MODELVIEW);
  for (int a = 0; a < 10; a++)
    for (int x = 0; x < 10; x++) {
      glLoadIdentity();
      glRotatef(angles[a], axes[x][0], axes[x][1], axes[x][2]);
      snprintf(name, sizeof name, "rot %g (%g,%g,%g)", angles[a], axes[x][0], axes[x][1], axes[x][2]);
      print_matrix(name, GL_MODELVIEW_MATRIX);
    }
  glLoadIdentity();
  glTranslatef(1.5f, -2.25f, 3.1f);
  glRotatef(33, 0.2f, 0.7f, -0.1f);
  glScalef(0.3f, 1.7f, -2.2f);
  glTranslatef(0.1f, 0.2f, 0.3f);
  print_matrix("chain", GL_MODELVIEW_MATRIX);
  glRotated(33.3, 0.2, 0.7, -0.1);
  print_matrix("chain, glRotated", GL_MODELVIEW_MATRIX);
  glTranslated(1.1, 2.2, 3.3);
  glScaled(1.1, 1.2, 1.3);
  print_matrix("chain, glTranslated, glScaled", GL_MODELVIEW_MATRIX);
  glRotatef(0, 1, 0, 0);
  print_matrix("chain, glRotatef(0)", GL_MODELVIEW_MATRIX);

  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glFrustum(-0.13, 0.17, -0.1, 0.11, 0.3, 17.5);
  print_matrix("frustum", GL_PROJECTION_MATRIX);
  glLoadIdentity();
  glOrtho(-1.3, 1.7, -0.9, 1.1, -2.5, 7.5);
  print_matrix("ortho", GL_PROJECTION_MATRIX);
  glFrustum(-0.13, 0.17, -0.1, 0.11, 0.3, 17.5);
  glRotatef(17, 1, 2, 3);
  print_matrix("ortho, frustum, rotate", GL_PROJECTION_MATRIX);
  static const GLfloat mf[16] = {1.1f, 0.2f, 0.3f, 0.01f, 0.4f, 1.5f, 0.6f, 0.02f,
                                 0.7f, 0.8f, 1.9f, 0.03f, 1,    2,    3,    1.04f};
  static const GLdouble md[16] = {1.1, 0.2, 0.3, 0.01, 0.4, 1.5, 0.6, 0.02,
                                  0.7, 0.8, 1.9, 0.03, 1,   2,   3,   1.04};
  glMultMatrixf(mf);
  glMultMatrixd(md);
  glMultTransposeMatrixf(mf);
  print_matrix("…, glMultMatrix f, d, T", GL_PROJECTION_MATRIX);
  glPopMatrix();

  const float nan = NAN, inf = INFINITY;
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(nan, 0, 0, 1);
  print_matrix("rot NaN", GL_MODELVIEW_MATRIX);
  glPushMatrix();
  glRotatef(nan, 1, 0, 0);
  print_matrix("rot NaN, pushed, rot NaN", GL_MODELVIEW_MATRIX);
  glPopMatrix();
  glLoadIdentity();
  glRotatef(30, nan, 0, 1);
  print_matrix("rot about (NaN,0,1)", GL_MODELVIEW_MATRIX);
  glLoadIdentity();
  glRotatef(30, inf, 0, 0);
  print_matrix("rot about (inf,0,0)", GL_MODELVIEW_MATRIX);
  glLoadIdentity();
  glTranslatef(inf, 0, 0);
  print_matrix("trans inf", GL_MODELVIEW_MATRIX);
  glLoadIdentity();
  glScalef(inf, 1, 1);
  glRotatef(30, 0, 0, 1);
  print_matrix("scale inf, rot", GL_MODELVIEW_MATRIX);
  glLoadIdentity();
  glScalef(inf, 1, 1);
  glTranslatef(1, 2, 3);
  print_matrix("scale inf, trans", GL_MODELVIEW_MATRIX);
  glLoadIdentity();
  glTranslatef(nan, 1, 1);
  glOrtho(-1, 1, -1, 1, -1, 1);
  print_matrix("trans NaN, ortho", GL_MODELVIEW_MATRIX);
  glLoadMatrixf(mf);
  glRotatef(nan, 0, 0, 1);
  print_matrix("load, rot NaN", GL_MODELVIEW_MATRIX);
  glLoadIdentity();
  glRotatef(nan, 0, 0, 1);
  print_matrix("load, identity, rot NaN", GL_MODELVIEW_MATRIX);
  err("the matrix commands");

  /* A quad under a rotation about a general axis. */
  glLoadIdentity();
  glTranslatef(W / 2, H / 2, 0);
  glRotatef(-77.7f, 0.3f, -0.5f, 2);
  glScalef(20, 20, 1);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_QUADS);
  glColor3f(1, 0, 0);
  glVertex2f(-1, -1);
  glColor3f(0, 1, 0);
  glVertex2f(1, -1);
  glColor3f(0, 0, 1);
  glVertex2f(1, 1);
  glColor3f(1, 1, 0);
  glVertex2f(-1, 1);
  glEnd();
  err("the quad");
  return finish(out, ctx, buf, W, H);
}
