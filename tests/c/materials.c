/* glMaterial inside glBegin/glEnd (GL 1.5 §2.6.3, §2.14.3): a lit triangle whose diffuse
 * colour changes at its second and third vertex, compiled into a display list and called
 * with a red material current (the first vertex takes it), then the errors of a bad
 * glMaterial inside a pair and the material state after. Prints a grid of pixels, the
 * errors and the material, which must be Mesa's.
 *
 * usage: materials */
#include <GL/osmesa.h>
#include <stdio.h>

static GLubyte buffer[32 * 32 * 4];

int main(void) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 32, 32)) return 1;
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, 1, 0, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glNormal3f(0, 0, 1);
  static const GLfloat red[] = {1, 0, 0, 1}, green[] = {0, 1, 0, 1}, blue[] = {0, 0, 1, 1};
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glVertex2f(0.05f, 0.05f);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, green);
  glVertex2f(0.95f, 0.05f);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
  glVertex2f(0.5f, 0.95f);
  glEnd();
  glEndList();
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glCallList(list);
  printf("list call                 0x%04x\n", glGetError());
  glBegin(GL_POINTS);
  glMaterialf(GL_FRONT, GL_SHININESS, 200);
  glEnd();
  printf("shininess 200 in a pair   0x%04x\n", glGetError());
  glBegin(GL_POINTS);
  glMaterialf(GL_FRONT, 0x1234, 2);
  glEnd();
  printf("bad name in a pair        0x%04x\n", glGetError());
  glFinish();
  for (int y = 28; y >= 4; y -= 8) {
    for (int x = 2; x < 32; x += 6) {
      const GLubyte *p = buffer + 4 * (y * 32 + x);
      printf("(%3d,%3d,%3d) ", p[0], p[1], p[2]);
    }
    printf("\n");
  }
  GLfloat d[4];
  glGetMaterialfv(GL_FRONT, GL_DIFFUSE, d);
  printf("front diffuse after       %g %g %g %g\n", d[0], d[1], d[2], d[3]);
  OSMesaDestroyContext(ctx);
  return 0;
}
