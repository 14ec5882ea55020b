/* glRotatef about one coordinate axis (positive or negative, any length) fills only that
 * axis's 2 x 2 block, so the axis keeps an exact 1 on the diagonal, as Mesa's
 * _math_matrix_rotate does. Each line: the upper 3 x 3 of the modelview matrix, exactly
 * (%a). The outputs on Mesa's OSMesa and on fixedfunc's library must be the same.
 *
 * usage: rotations */
#include <GL/osmesa.h>
#include <stdio.h>

int main(void) {
  static GLubyte buffer[8 * 8 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 1;
  static const float axes[][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 2}, {0, -3, 0}, {-1, 0, 0}};
  static const float angles[] = {90, 30, 45, 180, 270, -90, 10, 123.4f};
  for (unsigned a = 0; a < sizeof axes / sizeof axes[0]; a++)
    for (unsigned k = 0; k < sizeof angles / sizeof angles[0]; k++) {
      glLoadIdentity();
      glRotatef(angles[k], axes[a][0], axes[a][1], axes[a][2]);
      GLfloat m[16];
      glGetFloatv(GL_MODELVIEW_MATRIX, m);
      printf("rotate %g (%g, %g, %g):", angles[k], axes[a][0], axes[a][1], axes[a][2]);
      for (int i = 0; i < 11; i++)
        if (i % 4 != 3) printf(" %a", m[i]);
      printf("\n");
    }
  OSMesaDestroyContext(ctx);
  return 0;
}
