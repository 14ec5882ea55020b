/* Where the colours of lit and fogged fragments come from, printed one per line and drawn
 * a panel each: glMaterial on colours that COLOR_MATERIAL tracks (they keep the current
 * colour, GL 1.5 §2.14.3; the untracked ones and the other face are set), answered by
 * glGetMaterial and drawn after the tracking ends; the colour sum fogged (Mesa fogs the
 * sum unclamped, where GL 1.5 §3.9 clamps it first); a spot light whose direction is
 * zero (outside its cone on Mesa, but for the raster position). Run on Mesa's OSMesa and on
 * fixedfunc's library, the printed lines must be the same and the images match.
 *
 * usage: lit_colours [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 64
#define H 32
static GLubyte *buf;
static int panels;

/* The next 8×8 panel, a unit square facing the viewer, and its centre pixel. */
static void panel(const char *what) {
  int x = (panels % 8) * 8, y = (panels / 8) * 8;
  panels++;
  glBegin(GL_QUADS);
  glNormal3f(0, 0, 1);
  glVertex2i(x, y);
  glVertex2i(x + 8, y);
  glVertex2i(x + 8, y + 8);
  glVertex2i(x, y + 8);
  glEnd();
  GLubyte p[4] = {0};
  glReadPixels(x + 4, y + 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  printf("%-40s %d %d %d %d err 0x%x\n", what, p[0], p[1], p[2], p[3], glGetError());
}

/* A material colour of one face as glGetMaterialfv answers it. */
static void material(const char *what, GLenum face, GLenum pname) {
  GLfloat v[4] = {-1, -1, -1, -1};
  glGetMaterialfv(face, pname, v);
  printf("%-40s %g %g %g %g err 0x%x\n", what, v[0], v[1], v[2], v[3], glGetError());
}

static void materials(const char *what) {
  char line[64];
  snprintf(line, sizeof line, "%s: front ambient", what);
  material(line, GL_FRONT, GL_AMBIENT);
  snprintf(line, sizeof line, "%s: front diffuse", what);
  material(line, GL_FRONT, GL_DIFFUSE);
  snprintf(line, sizeof line, "%s: back ambient", what);
  material(line, GL_BACK, GL_AMBIENT);
  snprintf(line, sizeof line, "%s: back diffuse", what);
  material(line, GL_BACK, GL_DIFFUSE);
  snprintf(line, sizeof line, "%s: front specular", what);
  material(line, GL_FRONT, GL_SPECULAR);
}

static const GLfloat green[4] = {0, 1, 0, 1};
static const GLfloat blue[4] = {0, 0, 1, 1};
static const GLfloat grey[4] = {0.5f, 0.5f, 0.5f, 1};
static const GLfloat default_ambient[4] = {0.2f, 0.2f, 0.2f, 1};
static const GLfloat default_diffuse[4] = {0.8f, 0.8f, 0.8f, 1};
static const GLfloat black[4] = {0, 0, 0, 1};

/* The GL defaults of both faces' ambient, diffuse and specular colours. */
static void reset_materials(void) {
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, default_ambient);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, default_diffuse);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black);
}

/* glMaterial while COLOR_MATERIAL tracks some colours. */
static void colour_material(void) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);

  /* FRONT_AND_BACK, AMBIENT_AND_DIFFUSE (the default) tracks red; a green diffuse is
   * refused, and stays refused once the tracking ends. */
  glEnable(GL_COLOR_MATERIAL);
  glColor3f(1, 0, 0);
  panel("tracked red");
  glMaterialfv(GL_FRONT, GL_DIFFUSE, green);
  materials("diffuse set while tracked");
  glDisable(GL_COLOR_MATERIAL);
  materials("tracking ended");
  panel("after the tracking");

  /* FRONT, DIFFUSE tracks: AMBIENT_AND_DIFFUSE on both faces sets all but the front
   * diffuse; the specular is not tracked. */
  reset_materials();
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glColor3f(1, 0.5f, 0);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, blue);
  glMaterialfv(GL_FRONT, GL_SPECULAR, grey);
  materials("front diffuse tracked");
  panel("front diffuse tracked");
  glDisable(GL_COLOR_MATERIAL);
  panel("front diffuse no longer tracked");

  /* BACK, AMBIENT tracks: a front ambient is set. */
  reset_materials();
  glColorMaterial(GL_BACK, GL_AMBIENT);
  glEnable(GL_COLOR_MATERIAL);
  glColor3f(0, 1, 1);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, green);
  materials("back ambient tracked");
  glDisable(GL_COLOR_MATERIAL);

  /* glMaterial inside glBegin/glEnd on a tracked colour. */
  reset_materials();
  glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glColor3f(1, 1, 0);
  glBegin(GL_POINTS);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
  glMaterialfv(GL_FRONT, GL_AMBIENT, green);
  glVertex2i(-5, -5);
  glEnd();
  materials("set inside glBegin while tracked");
  glDisable(GL_COLOR_MATERIAL);
  panel("after the pair");

  reset_materials();
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glDisable(GL_LIGHTING);
}

/* The colour sum under fog: primary plus secondary above 1, fogged towards black by the
 * fog coordinate (LINEAR from 0 to 1). */
static void colour_sum_fogged(void) {
  static const GLfloat fog_black[4] = {0, 0, 0, 1};
  glEnable(GL_FOG);
  glFogfv(GL_FOG_COLOR, fog_black);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FOG_COORDINATE);
  glFogf(GL_FOG_START, 0);
  glFogf(GL_FOG_END, 1);
  glEnable(GL_COLOR_SUM);
  glFogCoordf(0.5f);
  glColor3f(0.75f, 0.25f, 0);
  glSecondaryColor3f(0.75f, 0.25f, 0);
  panel("sum 1.5 fogged by half");
  glColor3f(0.25f, 0.5f, 1);
  glSecondaryColor3f(0.5f, 0.75f, 1);
  glFogCoordf(0.25f);
  panel("sum above 1 fogged by a quarter");
  glDisable(GL_FOG);
  panel("sum above 1 unfogged");
  glDisable(GL_COLOR_SUM);
  glSecondaryColor3f(0, 0, 0);
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FRAGMENT_DEPTH);
}

/* A spot light at the eye with a zero spot direction: outside the cone of every cutoff
 * (Mesa's program), where a raster position is lit by (0)^exponent. */
static void zero_spot_direction(void) {
  static const GLfloat at_eye[4] = {0, 0, 1, 1};
  static const GLfloat zero[3] = {0, 0, 0};
  static const GLfloat dim[4] = {0.25f, 0.25f, 0.25f, 1};
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_AMBIENT, dim);
  glLightfv(GL_LIGHT0, GL_POSITION, at_eye);
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, zero);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 45);
  panel("zero spot direction, cutoff 45");
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 90);
  panel("zero spot direction, cutoff 90");
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 2);
  panel("zero spot direction, exponent 2");
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0);
  glRasterPos2i(4, 4);
  GLfloat c[4] = {-1, -1, -1, -1};
  glGetFloatv(GL_CURRENT_RASTER_COLOR, c);
  printf("%-40s %g %g %g %g err 0x%x\n", "raster colour, zero spot direction", c[0], c[1], c[2],
         c[3], glGetError());
  static const GLfloat down[3] = {0, 0, -1};
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, down);
  panel("spot towards the square, cutoff 90");
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
  glLightfv(GL_LIGHT0, GL_AMBIENT, black);
  glDisable(GL_LIGHTING);
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "lit_colours.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);

  colour_material();
  colour_sum_fogged();
  zero_spot_direction();

  return finish(out, ctx, buf, W, H);
}
