/* glPushAttrib and glPushClientAttrib save only the groups their mask names, and the
 * matching pop restores only those (GL 1.5 §6.1.14): each push names one group (or two,
 * or every group, or bits of no group) and the program changes state of several groups
 * before popping. One line per push/pop pair; the outputs on Mesa's OSMesa and on
 * fixedfunc's library must be the same.
 *
 * usage: attrib_masks */
#include <GL/osmesa.h>
#include <stdio.h>

static GLfloat vertices[3];

/* Sets state of six server groups to values unlike the defaults. The colour is read
 * back at once: Mesa 22.3 keeps a glColor not yet flushed in its vertex module, and some
 * pops (CURRENT_BIT with FOG_BIT, or GL_ALL_ATTRIB_BITS) let a later flush write it over
 * the restored colour, a Mesa fault the layer does not copy. */
static void change_server_state(void) {
  GLfloat flushed[4];
  glColor3f(1, 0, 0);
  glGetFloatv(GL_CURRENT_COLOR, flushed);
  glViewport(3, 4, 20, 10);
  glEnable(GL_FOG);
  glFogf(GL_FOG_DENSITY, 0.5f);
  glLineWidth(3);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glDepthFunc(GL_GREATER);
}

static void print_server_state(const char *what) {
  GLint vp[4], mode[2], func;
  GLfloat color[4], density, width;
  glGetIntegerv(GL_VIEWPORT, vp);
  glGetFloatv(GL_CURRENT_COLOR, color);
  glGetFloatv(GL_FOG_DENSITY, &density);
  glGetFloatv(GL_LINE_WIDTH, &width);
  glGetIntegerv(GL_POLYGON_MODE, mode);
  glGetIntegerv(GL_DEPTH_FUNC, &func);
  printf("%-34s color %g %g %g viewport %d %d %d %d fog %d density %g line %g poly 0x%x "
         "depth 0x%x err 0x%x\n",
         what, color[0], color[1], color[2], vp[0], vp[1], vp[2], vp[3], glIsEnabled(GL_FOG),
         density, width, mode[0], func, glGetError());
}

static void reset_server_state(void) {
  glColor3f(1, 1, 1);
  glViewport(0, 0, 32, 24);
  glDisable(GL_FOG);
  glFogf(GL_FOG_DENSITY, 1);
  glLineWidth(1);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDepthFunc(GL_LESS);
}

static void server(const char *what, GLbitfield mask) {
  reset_server_state();
  glPushAttrib(mask);
  change_server_state();
  glPopAttrib();
  print_server_state(what);
}

static void client(const char *what, GLbitfield mask) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glDisableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(4, GL_FLOAT, 0, NULL);
  glPushClientAttrib(mask);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, 7);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, vertices);
  glPopClientAttrib();
  GLint align, row, size;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &align);
  glGetIntegerv(GL_PACK_ROW_LENGTH, &row);
  glGetIntegerv(GL_VERTEX_ARRAY_SIZE, &size);
  printf("%-34s unpack align %d pack row %d varray %d size %d err 0x%x\n", what, align, row,
         glIsEnabled(GL_VERTEX_ARRAY), size, glGetError());
}

int main(void) {
  static GLubyte buffer[32 * 24 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 32, 24)) return 1;

  server("CURRENT", GL_CURRENT_BIT);
  server("VIEWPORT", GL_VIEWPORT_BIT);
  server("FOG", GL_FOG_BIT);
  server("ENABLE", GL_ENABLE_BIT);
  server("LINE", GL_LINE_BIT);
  server("POLYGON", GL_POLYGON_BIT);
  server("DEPTH_BUFFER", GL_DEPTH_BUFFER_BIT);
  server("CURRENT|FOG", GL_CURRENT_BIT | GL_FOG_BIT);
  server("LINE|POLYGON|VIEWPORT", GL_LINE_BIT | GL_POLYGON_BIT | GL_VIEWPORT_BIT);
  server("ALL_ATTRIB_BITS", GL_ALL_ATTRIB_BITS);
  server("0x000FFFFF", 0x000FFFFF);
  server("0", 0);
  server("0x40000000 (no group)", 0x40000000);

  client("CLIENT_PIXEL_STORE", GL_CLIENT_PIXEL_STORE_BIT);
  client("CLIENT_VERTEX_ARRAY", GL_CLIENT_VERTEX_ARRAY_BIT);
  client("PIXEL_STORE|VERTEX_ARRAY",
         GL_CLIENT_PIXEL_STORE_BIT | GL_CLIENT_VERTEX_ARRAY_BIT);
  client("CLIENT_ALL_ATTRIB_BITS", GL_CLIENT_ALL_ATTRIB_BITS);
  client("0", 0);
  client("0x4 (no group)", 0x4);

  OSMesaDestroyContext(ctx);
  return 0;
}
