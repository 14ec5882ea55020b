/* GL 1.3's cube maps (ARB_texture_cube_map) as environment-mapping programs of the era
 * used them: the six face targets of glTexImage2D, glTexSubImage2D, glCopyTexImage2D,
 * glCopyTexSubImage2D, glGetTexImage and glGetTexLevelParameter with their errors (the
 * cube target is not an image target, a face is not bindable, faces are square),
 * TEXTURE_BINDING_CUBE_MAP, MAX_CUBE_MAP_TEXTURE_SIZE, the TEXTURE_CUBE_MAP enable and the
 * attribute stack, texgen REFLECTION_MAP and NORMAL_MAP (INVALID_ENUM for Q); then panels
 * that sample a cube: its faces by explicit (s, t, r), the precedence of the cube map over
 * 2D, a reflection-mapped and a normal-mapped lit sphere, LINEAR with CLAMP_TO_EDGE, a
 * negative q, a missing face (the unit off), patched and copied faces, and a mipmapped
 * cube minified. Run on Mesa's OSMesa and on fixedfunc's library, the printed lines must be
 * the same and the images match.
 *
 * usage: cubemap [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"

#define W 128
#define H 64
#define P 32

static const GLubyte colours[6][3] = {{255, 0, 0},   {0, 255, 0},   {0, 0, 255},
                                      {255, 255, 0}, {0, 255, 255}, {255, 0, 255}};

/* A 4×4 face: its colour, the texels a ramp in x and y so a face's orientation shows. */
static void face_texels(int face, int size, GLubyte *out) {
  for (int y = 0; y < size; y++)
    for (int x = 0; x < size; x++) {
      GLubyte *t = out + 4 * (x + size * y);
      for (int c = 0; c < 3; c++) {
        int v = colours[face][c] / 2 + (x * 80 + y * 40) / size;
        t[c] = (GLubyte)(v > 255 ? 255 : v);
      }
      t[3] = 255;
    }
}

static void cube(GLuint name, int size, int faces) {
  GLubyte texels[16 * 16 * 4];
  glBindTexture(GL_TEXTURE_CUBE_MAP, name);
  for (int f = 0; f < faces; f++) {
    face_texels(f, size, texels);
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA8, size, size, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, texels);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

static void level(const char *what, GLenum target, int lvl, GLenum pname) {
  GLint v = -7;
  glGetTexLevelParameteriv(target, lvl, pname, &v);
  printf("%-40s %d  err 0x%x\n", what, v, glGetError());
}

static void errors_and_queries(void) {
  GLubyte texels[4 * 4 * 4] = {0};
  GLint v;
  ints("MAX_CUBE_MAP_TEXTURE_SIZE", GL_MAX_CUBE_MAP_TEXTURE_SIZE);
  ints("TEXTURE_BINDING_CUBE_MAP", GL_TEXTURE_BINDING_CUBE_MAP);
  ints("TEXTURE_CUBE_MAP enabled", GL_TEXTURE_CUBE_MAP);
  glTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  err("glTexImage2D(TEXTURE_CUBE_MAP)");
  glBindTexture(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 1);
  err("glBindTexture(a face)");
  glBindTexture(GL_TEXTURE_CUBE_MAP, 9);
  err("glBindTexture(TEXTURE_CUBE_MAP, 9)");
  ints("TEXTURE_BINDING_CUBE_MAP", GL_TEXTURE_BINDING_CUBE_MAP);
  glBindTexture(GL_TEXTURE_2D, 9);
  err("glBindTexture(TEXTURE_2D, the cube)");
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 2, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               texels);
  err("a 2x4 face");
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 16385, 16385, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, NULL);
  err("a 16385 face");
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 15, GL_RGBA, 1, 1, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, texels);
  err("level 15");
  glTexImage1D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               texels);
  err("glTexImage1D(a face)");
  glTexImage3D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 2, 2, 1, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, texels);
  err("glTexImage3D(a face)");
  for (int f = 0; f < 6; f++)
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA, 1, 1, 0, GL_RGB,
                 GL_UNSIGNED_BYTE, colours[f]);
  err("six 1x1 faces");
  level("-Y TEXTURE_WIDTH", GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, GL_TEXTURE_WIDTH);
  level("TEXTURE_CUBE_MAP TEXTURE_WIDTH", GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH);
  level("+Z level 1 TEXTURE_WIDTH", GL_TEXTURE_CUBE_MAP_POSITIVE_Z, 1, GL_TEXTURE_WIDTH);
  GLubyte got[4] = {0, 0, 0, 0};
  glGetTexImage(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_RGBA, GL_UNSIGNED_BYTE, got);
  printf("%-40s %d %d %d  err 0x%x\n", "glGetTexImage(-Z)", got[0], got[1], got[2],
         glGetError());
  glGetTexImage(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, GL_UNSIGNED_BYTE, got);
  err("glGetTexImage(TEXTURE_CUBE_MAP)");
  glTexSubImage2D(GL_TEXTURE_CUBE_MAP, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  err("glTexSubImage2D(TEXTURE_CUBE_MAP)");
  glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                  texels);
  err("glTexSubImage2D(+Y)");
  glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, 1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                  texels);
  err("glTexSubImage2D(+Y) outside");
  glCopyTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 0, 0, 2, 2, 0);
  err("glCopyTexImage2D(TEXTURE_CUBE_MAP)");
  glCopyTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, GL_RGBA, 0, 0, 2, 4, 0);
  err("glCopyTexImage2D(+Y) 2x4");
  glCopyTexSubImage2D(GL_TEXTURE_CUBE_MAP, 0, 0, 0, 0, 0, 1, 1);
  err("glCopyTexSubImage2D(TEXTURE_CUBE_MAP)");
  glCopyTexSubImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_X, 0, 0, 0, 0, 0, 1, 1);
  err("glCopyTexSubImage2D(-X)");
  glTexParameteri(GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  err("glTexParameteri(a face)");
  v = -7;
  glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, &v);
  printf("%-40s 0x%x  err 0x%x\n", "TEXTURE_WRAP_R", v, glGetError());
  glEnable(GL_TEXTURE_CUBE_MAP_POSITIVE_X);
  err("glEnable(a face)");
  glEnable(GL_TEXTURE_CUBE_MAP);
  ints("TEXTURE_CUBE_MAP enabled", GL_TEXTURE_CUBE_MAP);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_TEXTURE_CUBE_MAP);
  glPopAttrib();
  ints("enabled after ENABLE_BIT", GL_TEXTURE_CUBE_MAP);
  glPushAttrib(GL_TEXTURE_BIT);
  glDisable(GL_TEXTURE_CUBE_MAP);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glPopAttrib();
  ints("enabled after TEXTURE_BIT", GL_TEXTURE_CUBE_MAP);
  ints("binding after TEXTURE_BIT", GL_TEXTURE_BINDING_CUBE_MAP);
  glDisable(GL_TEXTURE_CUBE_MAP);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  err("S REFLECTION_MAP");
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  err("R NORMAL_MAP");
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  err("Q REFLECTION_MAP");
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  err("Q NORMAL_MAP");
  v = -7;
  glGetTexGeniv(GL_R, GL_TEXTURE_GEN_MODE, &v);
  printf("%-40s 0x%x  err 0x%x\n", "R TEXTURE_GEN_MODE", v, glGetError());
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               texels);
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  err("glGenerateMipmap, faces differ");
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP_POSITIVE_X);
  err("glGenerateMipmap(a face)");
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
}

static void panel(int i) {
  glViewport((i % 4) * P, (i / 4) * P, P, P);
}

/* Six quads, one per face, each sampled at directions around its face's axis. */
static void faces_by_direction(void) {
  static const float axes[6][3][3] = {
      /* axis, s-direction, t-direction */
      {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},   {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
      {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}}};
  glBegin(GL_QUADS);
  for (int f = 0; f < 6; f++) {
    float x0 = -1 + (f % 3) * (2.0f / 3), y0 = -1 + (f / 3) * 1.0f;
    static const float corner[4][2] = {{-0.9f, -0.9f}, {0.9f, -0.9f}, {0.9f, 0.9f}, {-0.9f, 0.9f}};
    static const float at[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 4; k++) {
      const float(*a)[3] = axes[f];
      float d[3];
      for (int c = 0; c < 3; c++) d[c] = a[0][c] + corner[k][0] * a[1][c] + corner[k][1] * a[2][c];
      glTexCoord3f(d[0], d[1], d[2]);
      glVertex2f(x0 + at[k][0] * (2.0f / 3), y0 + at[k][1]);
    }
  }
  glEnd();
}

/* A lit sphere of 16 × 12 quads, normals its positions. */
static void sphere(float radius) {
  const float pi = 3.14159265f;
  for (int j = 0; j < 12; j++) {
    float a0 = pi * j / 12 - pi / 2, a1 = pi * (j + 1) / 12 - pi / 2;
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= 16; i++) {
      float b = 2 * pi * i / 16;
      for (int k = 1; k >= 0; k--) {
        float a = k ? a1 : a0;
        float n[3] = {cosf(a) * cosf(b), sinf(a), cosf(a) * sinf(b)};
        glNormal3fv(n);
        glVertex3f(radius * n[0], radius * n[1], radius * n[2]);
      }
    }
    glEnd();
  }
}

static void texgen(GLenum mode) {
  for (GLenum c = GL_S; c <= GL_R; c++) {
    glTexGeni(c, GL_TEXTURE_GEN_MODE, mode);
  }
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glEnable(GL_TEXTURE_GEN_R);
}

static void no_texgen(void) {
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  glDisable(GL_TEXTURE_GEN_R);
}

static void lit_sphere(void) {
  static const GLfloat dir[4] = {0.3f, 0.5f, 1, 0};
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.6, 0.6, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -3);
  glRotatef(30, 1, 1, 0);
  sphere(1);
  glLoadIdentity();
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
}

static void panels(void) {
  GLubyte texels[16 * 16 * 4];
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  cube(1, 4, 6);
  glEnable(GL_TEXTURE_CUBE_MAP);
  /* 0: the six faces by explicit directions, NEAREST. */
  panel(0);
  faces_by_direction();
  /* 1: the cube map wins over an enabled 2D texture. */
  panel(1);
  glBindTexture(GL_TEXTURE_2D, 2);
  face_texels(3, 4, texels);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  faces_by_direction();
  glDisable(GL_TEXTURE_2D);
  /* 2: reflection map on a lit sphere, LINEAR and CLAMP_TO_EDGE. */
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  panel(2);
  texgen(GL_REFLECTION_MAP);
  lit_sphere();
  /* 3: normal map on a lit sphere. */
  panel(3);
  texgen(GL_NORMAL_MAP);
  lit_sphere();
  no_texgen();
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  /* 4: a negative q (the direction divided by it). */
  panel(4);
  glBegin(GL_QUADS);
  glTexCoord4f(1, -0.5f, -0.5f, -1);
  glVertex2f(-1, -1);
  glTexCoord4f(1, 0.5f, -0.5f, -1);
  glVertex2f(1, -1);
  glTexCoord4f(1, 0.5f, 0.5f, -1);
  glVertex2f(1, 1);
  glTexCoord4f(1, -0.5f, 0.5f, -1);
  glVertex2f(-1, 1);
  glEnd();
  /* 5: a cube missing its -Z face: the unit is off, the quads take the colour. */
  panel(5);
  cube(3, 4, 5);
  glColor3f(0.8f, 0.6f, 0.2f);
  faces_by_direction();
  glColor3f(1, 1, 1);
  /* 6: faces patched by glTexSubImage2D and glCopyTexSubImage2D. */
  panel(6);
  cube(4, 4, 6);
  face_texels(5, 2, texels);
  glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE,
                  texels);
  glCopyTexSubImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_X, 0, 0, 0, 8, 8, 2, 2);
  glCopyTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Z, 0, GL_RGBA8, 40, 8, 4, 4, 0);
  faces_by_direction();
  /* 7: a mipmapped cube minified (GENERATE_MIPMAP). */
  panel(7);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 5);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_GENERATE_MIPMAP, GL_TRUE);
  for (int f = 0; f < 6; f++) {
    face_texels(f, 16, texels);
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA8, 16, 16, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, texels);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glScalef(0.3f, 0.3f, 1);
  faces_by_direction();
  glLoadIdentity();
  glDisable(GL_TEXTURE_CUBE_MAP);
  err("panels");
}

int main(int argc, char **argv) {
  const char *path = argc > 1 ? argv[1] : "cubemap.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  errors_and_queries();
  panels();
  glFinish();
  if (!write_ppm(path, buf, W, H)) return 1;
  OSMesaDestroyContext(ctx);
  free(buf);
  return 0;
}
