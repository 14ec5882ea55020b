/* Float and non-finite parameters, as Mesa 22.3 takes them. Prints the error after each
 * call and the state it left:
 * - NaN passes Mesa's range checks (`v < lo || v > hi`) of SPOT_EXPONENT, SPOT_CUTOFF, the
 *   attenuations and SHININESS, scalar and vector forms, and reads back NaN; ±∞ beyond the
 *   range are INVALID_VALUE;
 * - a NaN alpha reference and texture priority read back 0; a texture's LOD parameters
 *   read as integers are rounded and clamped, the environment's LOD bias truncated;
 * - glPixelStoref converts as (GLint) lroundf: 5e9 wraps, 1e20, ±∞ and NaN give 0;
 * - a token passed as a float with a fraction: glTexParameterf rounds, glTexParameterfv and
 *   the others truncate, glLightModelf{,v} want it exact;
 * - the vector forms of the scalar parameters (glTexGeniv(TEXTURE_GEN_MODE),
 *   glLightModelfv(TWO_SIDE) …) are taken.
 * A NaN depth drawn by glDrawPixels is written as 0.
 * Then draws six lit quads, each under one NaN: spot cutoff, spot exponent, shininess and
 * the three attenuations; and bitmaps advanced by a fraction and by NaN.
 *
 * usage: float_params [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "report.h"

#define W 192
#define H 128

static void floats(const char *what, GLenum pname, int n) {
  GLfloat v[4] = {-7, -7, -7, -7};
  glGetFloatv(pname, v);
  printf("%-40s", what);
  for (int i = 0; i < n; i++) printf(" %g", v[i]);
  printf("  err 0x%x\n", glGetError());
}

static void light_value(const char *what, GLenum pname, GLfloat v) {
  glLightf(GL_LIGHT0, pname, v);
  GLenum e = glGetError();
  GLfloat back = -7;
  glGetLightfv(GL_LIGHT0, pname, &back);
  printf("glLightf(%s, %g)%*s err 0x%x  reads %g\n", what, v, 12, "", e, back);
}

static const float fractions[] = {0.25f, 0.5f, 0.75f, -0.25f, -0.5f, -0.75f};

static void tex_parameter(const char *what, GLenum pname, GLenum token, GLint reset) {
  for (int i = 0; i < 6; i++) {
    GLfloat v = (float)token + fractions[i];
    glTexParameterf(GL_TEXTURE_2D, pname, v);
    GLenum e = glGetError();
    GLint back = -7;
    glGetTexParameteriv(GL_TEXTURE_2D, pname, &back);
    glTexParameterfv(GL_TEXTURE_2D, pname, &v);
    GLenum ev = glGetError();
    GLint backv = -7;
    glGetTexParameteriv(GL_TEXTURE_2D, pname, &backv);
    printf("glTexParameterf %s %+.2f  err 0x%x 0x%x  fv err 0x%x 0x%x\n", what, fractions[i], e,
           back, ev, backv);
    glTexParameteri(GL_TEXTURE_2D, pname, reset);
  }
}

/* The quad of panel (column, row), 64×64 with a 2-pixel margin. */
static void quad(int column, int row) {
  glNormal3f(0, 0, 1);
  glRectf(64 * column + 2, 64 * row + 2, 64 * column + 62, 64 * row + 62);
}

/* The quad of panel (column, row) lit with LIGHT0's `pname` NaN, then `pname` back to
 * `kept`. */
static void quad_under_nan(GLenum pname, GLfloat kept, int column, int row) {
  glLightf(GL_LIGHT0, pname, NAN);
  quad(column, row);
  glLightf(GL_LIGHT0, pname, kept);
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "float_params.ppm";
  OSMesaContext ctx;
  GLubyte *buf = open_window(&ctx, W, H);
  if (!buf) return 2;
  const float nan = NAN, inf = INFINITY;
  GLfloat v[4];

  light_value("SPOT_EXPONENT", GL_SPOT_EXPONENT, nan);
  light_value("SPOT_EXPONENT", GL_SPOT_EXPONENT, inf);
  light_value("SPOT_CUTOFF", GL_SPOT_CUTOFF, nan);
  light_value("SPOT_CUTOFF", GL_SPOT_CUTOFF, inf);
  light_value("CONSTANT_ATTENUATION", GL_CONSTANT_ATTENUATION, nan);
  light_value("LINEAR_ATTENUATION", GL_LINEAR_ATTENUATION, inf);
  light_value("QUADRATIC_ATTENUATION", GL_QUADRATIC_ATTENUATION, -inf);
  GLfloat nans[4] = {nan, nan, nan, nan};
  glLightfv(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, nans);
  err("glLightfv(QUADRATIC_ATTENUATION, NaN)");
  glMaterialf(GL_FRONT, GL_SHININESS, nan);
  err("glMaterialf(SHININESS, NaN)");
  glMaterialfv(GL_BACK, GL_SHININESS, nans);
  err("glMaterialfv(BACK, SHININESS, NaN)");
  glGetMaterialfv(GL_BACK, GL_SHININESS, v);
  printf("back SHININESS %g\n", v[0]);
  glMaterialf(GL_FRONT, GL_SHININESS, inf);
  err("glMaterialf(SHININESS, inf)");
  glBegin(GL_TRIANGLES);
  glMaterialf(GL_FRONT, GL_SHININESS, nan);
  glEnd();
  err("glMaterialf(SHININESS, NaN) in glBegin");

  glAlphaFunc(GL_LESS, nan);
  floats("ALPHA_TEST_REF after NaN", GL_ALPHA_TEST_REF, 1);
  ints("ALPHA_TEST_REF after NaN (int)", GL_ALPHA_TEST_REF);
  glAlphaFunc(GL_ALWAYS, 0);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, nan);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, v);
  printf("TEXTURE_PRIORITY after NaN %g  err 0x%x\n", v[0], glGetError());
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 1);

  static const float stores[] = {2.5f, 3.4f, -0.4f, -0.6f, 3e9f, 5e9f, 1e20f, -1e20f};
  for (unsigned i = 0; i < sizeof stores / sizeof stores[0]; i++) {
    glPixelStoref(GL_UNPACK_ROW_LENGTH, stores[i]);
    GLenum e = glGetError();
    GLint back = -7;
    glGetIntegerv(GL_UNPACK_ROW_LENGTH, &back);
    printf("glPixelStoref(UNPACK_ROW_LENGTH, %g)  err 0x%x  reads %d\n", stores[i], e, back);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  }
  glPixelStoref(GL_UNPACK_SKIP_ROWS, nan);
  ints("UNPACK_SKIP_ROWS after NaN", GL_UNPACK_SKIP_ROWS);
  glPixelStoref(GL_PACK_SKIP_PIXELS, inf);
  ints("PACK_SKIP_PIXELS after inf", GL_PACK_SKIP_PIXELS);
  glPixelStoref(GL_UNPACK_ALIGNMENT, 1.5f);
  ints("UNPACK_ALIGNMENT after 1.5", GL_UNPACK_ALIGNMENT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);

  /* A texture's LOD parameters read as integers are rounded and clamped (NaN reads
   * −2³¹); the environment's LOD bias is cast, truncating. */
  static const float lods[] = {2.5f, -2.5f, 0.7f, 1e10f, -1e10f, NAN};
  for (unsigned i = 0; i < sizeof lods / sizeof lods[0]; i++) {
    GLint min = -7, max = -7, bias = -7, env = -7;
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, lods[i]);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, lods[i]);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, lods[i]);
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, lods[i]);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, &min);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, &max);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, &bias);
    glGetTexEnviv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &env);
    printf("LOD %g  MIN_LOD %d MAX_LOD %d LOD_BIAS %d  env LOD_BIAS %d  err 0x%x\n", lods[i], min,
           max, bias, env, glGetError());
  }
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -1000);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 1000);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0);

  tex_parameter("MIN_FILTER", GL_TEXTURE_MIN_FILTER, GL_LINEAR, GL_NEAREST_MIPMAP_LINEAR);
  tex_parameter("WRAP_S", GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE, GL_REPEAT);
  tex_parameter("BASE_LEVEL", GL_TEXTURE_BASE_LEVEL, 2, 0);
  tex_parameter("GENERATE_MIPMAP", GL_GENERATE_MIPMAP, 1, 0);
  for (int i = 0; i < 6; i++) {
    GLint back = -7;
    GLfloat f = (float)GL_SEPARATE_SPECULAR_COLOR + fractions[i];
    glLightModelf(GL_LIGHT_MODEL_COLOR_CONTROL, f);
    GLenum e = glGetError();
    glLightModelfv(GL_LIGHT_MODEL_COLOR_CONTROL, &f);
    GLenum ev = glGetError();
    f = (float)GL_EXP2 + fractions[i];
    glFogfv(GL_FOG_MODE, &f);
    GLenum ef = glGetError();
    glGetIntegerv(GL_FOG_MODE, &back);
    glFogi(GL_FOG_MODE, GL_EXP);
    printf("fraction %+.2f  COLOR_CONTROL f 0x%x fv 0x%x  glFogfv(FOG_MODE) 0x%x 0x%x\n",
           fractions[i], e, ev, ef, back);
  }
  GLint mode = GL_SPHERE_MAP;
  glTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &mode);
  GLfloat fmode = GL_OBJECT_LINEAR + 0.75f;
  glTexGenfv(GL_T, GL_TEXTURE_GEN_MODE, &fmode);
  GLdouble dmode = GL_EYE_LINEAR;
  glTexGendv(GL_R, GL_TEXTURE_GEN_MODE, &dmode);
  err("glTexGen{i,f,d}v(TEXTURE_GEN_MODE)");
  GLint modes[3];
  glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &modes[0]);
  glGetTexGeniv(GL_T, GL_TEXTURE_GEN_MODE, &modes[1]);
  glGetTexGeniv(GL_R, GL_TEXTURE_GEN_MODE, &modes[2]);
  printf("TEXTURE_GEN_MODE S 0x%x T 0x%x R 0x%x\n", modes[0], modes[1], modes[2]);
  GLfloat one = 1, separate = GL_SEPARATE_SPECULAR_COLOR;
  glLightModelfv(GL_LIGHT_MODEL_TWO_SIDE, &one);
  glLightModelfv(GL_LIGHT_MODEL_LOCAL_VIEWER, &one);
  glLightModelfv(GL_LIGHT_MODEL_COLOR_CONTROL, &separate);
  err("glLightModelfv(scalar parameters)");
  ints("LIGHT_MODEL_TWO_SIDE", GL_LIGHT_MODEL_TWO_SIDE);
  ints("LIGHT_MODEL_LOCAL_VIEWER", GL_LIGHT_MODEL_LOCAL_VIEWER);
  ints("LIGHT_MODEL_COLOR_CONTROL", GL_LIGHT_MODEL_COLOR_CONTROL);
  glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, nan);
  ints("LIGHT_MODEL_TWO_SIDE after NaN", GL_LIGHT_MODEL_TWO_SIDE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 0);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);

  /* Depths drawn by glDrawPixels: a NaN is written as 0, ±∞ clamped. */
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  static const GLfloat depths[4] = {NAN, INFINITY, -INFINITY, 0.25f};
  glRasterPos2i(0, 0);
  glDrawPixels(4, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  GLuint drawn[4] = {7, 7, 7, 7};
  glReadPixels(0, 0, 4, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, drawn);
  printf("glDrawPixels depths NaN, inf, -inf, 0.25: %x %x %x %x  err 0x%x\n", drawn[0], drawn[1],
         drawn[2], drawn[3], glGetError());
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);

  /* Six lit quads (lit at their corners), each under one NaN parameter: quadratic
   * attenuation, spot cutoff, linear attenuation; constant attenuation, spot exponent (in a
   * 60° cone that leaves the outer corners out), shininess (under a directional light, so
   * that the exponent shows: Mesa lights it as 128). */
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  static const GLfloat position[] = {W / 2, H / 2, 40, 1}, direction[] = {0, 0, -1};
  static const GLfloat sun[] = {0.3f, 0.2f, 1, 0};
  static const GLfloat white[] = {1, 1, 1, 1}, grey[] = {0.6f, 0.5f, 0.4f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, direction);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, grey);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0);
  glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0);
  glMaterialf(GL_FRONT, GL_SHININESS, 16);
  quad_under_nan(GL_QUADRATIC_ATTENUATION, 0, 0, 0);
  quad_under_nan(GL_SPOT_CUTOFF, 180, 1, 0);
  quad_under_nan(GL_LINEAR_ATTENUATION, 0, 2, 0);
  quad_under_nan(GL_CONSTANT_ATTENUATION, 1, 0, 1);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 60);
  quad_under_nan(GL_SPOT_EXPONENT, 0, 1, 1);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
  glLightfv(GL_LIGHT0, GL_POSITION, sun);
  glMaterialf(GL_FRONT, GL_SHININESS, nan);
  quad(2, 1);
  err("the lit quads");

  /* Bitmaps along a row with a fractional advance, then two after a NaN advance: the
   * first is drawn where the position was, the second at x = 0 as Mesa floors a NaN. */
  glDisable(GL_LIGHTING);
  glColor3f(1, 1, 0);
  static const GLubyte box[8] = {0xff, 0x81, 0x81, 0x81, 0x81, 0x81, 0x81, 0xff};
  glRasterPos2f(3.6f, 118);
  for (int i = 0; i < 24; i++) glBitmap(8, 8, 0, 0, 7.3f, 0.1f, box);
  glRasterPos2f(20, 100);
  glBitmap(8, 8, 0, 0, nan, 0, box);
  glBitmap(8, 8, 0, 0, 0, 0, box);
  err("the bitmaps");
  return finish(out, ctx, buf, W, H);
}
