/* The evaluator enables a program of the era sets in its init code: glEnable(AUTO_NORMAL)
 * and MAP1_* / MAP2_*, answered by glIsEnabled and glGetBooleanv, kept by the ENABLE_BIT
 * and EVAL_BIT attribute groups, with no error (evaluating itself is left out). One line
 * per answer, printed as Mesa prints it.
 *
 * usage: eval_enables */
#include <GL/osmesa.h>
#include <stdio.h>
#include "report.h"

static void enabled(const char *what, GLenum cap) {
  GLboolean b = 7;
  glGetBooleanv(cap, &b);
  printf("%-36s %d %d  err 0x%x\n", what, glIsEnabled(cap), b, glGetError());
}

int main(void) {
  static GLubyte buf[4 * 8 * 8];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 8, 8)) return 1;
  enabled("AUTO_NORMAL default", GL_AUTO_NORMAL);
  enabled("MAP2_VERTEX_3 default", GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  err("glEnable(AUTO_NORMAL)");
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_MAP1_TEXTURE_COORD_2);
  err("glEnable(MAP2_VERTEX_3, MAP1_TEXTURE_COORD_2)");
  enabled("AUTO_NORMAL", GL_AUTO_NORMAL);
  enabled("MAP2_VERTEX_3", GL_MAP2_VERTEX_3);
  enabled("MAP1_TEXTURE_COORD_2", GL_MAP1_TEXTURE_COORD_2);
  enabled("MAP2_TEXTURE_COORD_2", GL_MAP2_TEXTURE_COORD_2);
  glPushAttrib(GL_EVAL_BIT);
  glDisable(GL_AUTO_NORMAL);
  glDisable(GL_MAP2_VERTEX_3);
  enabled("AUTO_NORMAL inside EVAL_BIT", GL_AUTO_NORMAL);
  glPopAttrib();
  enabled("AUTO_NORMAL after EVAL_BIT", GL_AUTO_NORMAL);
  enabled("MAP2_VERTEX_3 after EVAL_BIT", GL_MAP2_VERTEX_3);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_MAP1_TEXTURE_COORD_2);
  glPopAttrib();
  enabled("MAP1_TEXTURE_COORD_2 after ENABLE_BIT", GL_MAP1_TEXTURE_COORD_2);
  glPushAttrib(GL_LIGHTING_BIT);
  glDisable(GL_AUTO_NORMAL);
  glPopAttrib();
  enabled("AUTO_NORMAL after LIGHTING_BIT", GL_AUTO_NORMAL);
  glBegin(GL_POINTS);
  glEnable(GL_AUTO_NORMAL);
  glEnd();
  err("glEnable inside glBegin");
  OSMesaDestroyContext(ctx);
  return 0;
}
