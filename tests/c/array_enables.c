/* glEnable and glDisable of the client arrays' tokens, as Mesa's compatibility context
 * answers them: taken as glEnableClientState and glDisableClientState (no error), read
 * back by glIsEnabled, not restored by glPopAttrib(ENABLE_BIT) but by the client
 * attribute stack, compiled into a display list and run with it, INVALID_OPERATION
 * inside glBegin/glEnd. A triangle drawn from a vertex array enabled this way.
 *
 * usage: array_enables [out.ppm] */
#include <GL/osmesa.h>
#include <stdio.h>
#include "report.h"

#define W 16
#define H 16

static void on(const char *what, GLenum cap) {
  printf("%-40s %d  err 0x%x\n", what, glIsEnabled(cap), glGetError());
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "array_enables.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 2;

  static const GLenum caps[] = {GL_VERTEX_ARRAY,         GL_NORMAL_ARRAY,
                                GL_COLOR_ARRAY,          GL_INDEX_ARRAY,
                                GL_TEXTURE_COORD_ARRAY,  GL_EDGE_FLAG_ARRAY,
                                GL_FOG_COORD_ARRAY,      GL_SECONDARY_COLOR_ARRAY};
  char name[64];
  for (unsigned i = 0; i < sizeof caps / sizeof caps[0]; i++) {
    glEnable(caps[i]);
    snprintf(name, sizeof name, "glEnable(0x%04x)", caps[i]);
    err(name);
    on("  enabled", caps[i]);
    glDisable(caps[i]);
    on("  after glDisable", caps[i]);
  }

  glEnable(GL_VERTEX_ARRAY);
  static const GLfloat triangle[] = {-1, -1, 1, -1, 0, 1};
  glVertexPointer(2, GL_FLOAT, 0, triangle);
  glColor3f(1, 1, 1);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  err("glDrawArrays from the enabled array");

  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDisable(GL_VERTEX_ARRAY);
  glPopClientAttrib();
  on("VERTEX_ARRAY after glPopClientAttrib", GL_VERTEX_ARRAY);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_VERTEX_ARRAY);
  glPopAttrib();
  on("VERTEX_ARRAY after glPopAttrib", GL_VERTEX_ARRAY);

  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEnable(GL_COLOR_ARRAY);
  glEndList();
  err("glEnable(COLOR_ARRAY) compiled");
  on("COLOR_ARRAY after compiling", GL_COLOR_ARRAY);
  glCallList(list);
  on("COLOR_ARRAY after glCallList", GL_COLOR_ARRAY);
  glDisable(GL_COLOR_ARRAY);

  glBegin(GL_POINTS);
  glEnable(GL_NORMAL_ARRAY);
  glEnd();
  err("glEnable(NORMAL_ARRAY) in glBegin");
  on("NORMAL_ARRAY after it", GL_NORMAL_ARRAY);
  return finish(out, ctx, buf, W, H);
}
