/* GL 1.4's secondary colour and fog coordinate (EXT_secondary_color, EXT_fog_coord) as
 * programs of the era used them: glSecondaryColor* and glFogCoord* in and outside
 * glBegin/glEnd, their arrays in client memory and in a buffer object, glArrayElement,
 * display lists, COLOR_SUM with lighting off (the sum after texturing, only RGB), flat
 * shading (the provoking vertex's secondary colour), FOG_COORD_SRC (the magnitude of the
 * coordinate, taken per vertex), the raster distance it gives glRasterPos and glWindowPos,
 * glBitmap and glDrawPixels under COLOR_SUM, stippled lines; their errors, queries and
 * attribute groups. Run on Mesa's OSMesa and on fixedfunc's library, the printed lines must
 * be the same and the images match.
 *
 * usage: secondary [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 96
#define H 96
static unsigned char *buf;

static void f4(const char *what, GLenum p) {
  GLfloat v[4] = {-7, -7, -7, -7};
  glGetFloatv(p, v);
  printf("%-34s %g %g %g %g err %x\n", what, v[0], v[1], v[2], v[3], glGetError());
}

static void i4(const char *what, GLenum p) {
  GLint v[4] = {-7, -7, -7, -7};
  glGetIntegerv(p, v);
  printf("%-34s %d %d %d %d err %x\n", what, v[0], v[1], v[2], v[3], glGetError());
}

static void px(const char *what, int x, int y) {
  glFinish();
  const unsigned char *p = buf + 4 * (y * W + x);
  printf("%-34s %d %d %d %d\n", what, p[0], p[1], p[2], p[3]);
}

/* Panel k of a 4 x 4 grid (24 x 24 pixels each) as the viewport. */
static void panel(int k) { glViewport((k % 4) * 24, (k / 4) * 24, 24, 24); }

static void state_and_errors(void) {
  f4("secondary initial", GL_CURRENT_SECONDARY_COLOR);
  f4("fog coord initial", GL_CURRENT_FOG_COORD);
  ints("fog coord src initial", GL_FOG_COORD_SRC);
  ints("color sum initial", GL_COLOR_SUM);
  glSecondaryColor3f(0.5f, 2, -1);
  f4("secondary 3f", GL_CURRENT_SECONDARY_COLOR);
  glSecondaryColor3ub(255, 128, 0);
  f4("secondary 3ub", GL_CURRENT_SECONDARY_COLOR);
  glSecondaryColor3bEXT(127, -128, 64);
  f4("secondary 3b EXT", GL_CURRENT_SECONDARY_COLOR);
  glSecondaryColor3usv((GLushort[]){65535, 0, 32768});
  f4("secondary 3usv", GL_CURRENT_SECONDARY_COLOR);
  glSecondaryColor3i(2147483647, 0, -2147483647);
  i4("secondary as ints", GL_CURRENT_SECONDARY_COLOR);
  glSecondaryColor3d(0.25, 0.5, 0.75);
  f4("secondary 3d", GL_CURRENT_SECONDARY_COLOR);
  glFogCoordf(3.5f);
  f4("fog coord 3.5", GL_CURRENT_FOG_COORD);
  ints("fog coord as int", GL_CURRENT_FOG_COORD);
  glFogCoorddvEXT((GLdouble[]){-2.25});
  f4("fog coord dv EXT", GL_CURRENT_FOG_COORD);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  ints("fog coord src set", GL_FOG_COORD_SRC);
  glFogi(GL_FOG_COORD_SRC, GL_ZERO);
  err("fog coord src ZERO");
  glFogf(GL_FOG_COORD_SRC, 3.0f);
  err("fog coord src 3");
  glFogi(GL_FOG_COORDINATE_SOURCE, GL_FRAGMENT_DEPTH);
  ints("fog coord src back", GL_FOG_COORD_SRC);
  GLint mode = GL_EXP2;
  glFogiv(GL_FOG_MODE, &mode);
  ints("fogiv mode", GL_FOG_MODE);
  GLfloat fmode = GL_LINEAR;
  glFogfv(GL_FOG_MODE, &fmode);
  ints("fogfv mode", GL_FOG_MODE);
  mode = 5;
  glFogiv(GL_FOG_MODE, &mode);
  err("fogiv mode 5");
  mode = GL_FOG_COORD;
  glFogiv(GL_FOG_COORD_SRC, &mode);
  ints("fogiv src", GL_FOG_COORD_SRC);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glFogi(GL_FOG_MODE, GL_EXP);

  static GLfloat data[64];
  for (int s = 0; s <= 5; s++) {
    glSecondaryColorPointer(s, GL_FLOAT, 0, data);
    printf("secondary pointer size %d err %x\n", s, glGetError());
  }
  GLenum types[] = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT,
                    GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE, GL_FIXED};
  for (int t = 0; t < 9; t++) {
    glSecondaryColorPointer(3, types[t], 0, data);
    printf("secondary pointer type %x err %x\n", types[t], glGetError());
    glFogCoordPointer(types[t], 0, data);
    printf("fog coord pointer type %x err %x\n", types[t], glGetError());
  }
  glSecondaryColorPointer(3, GL_FLOAT, -1, data);
  err("secondary pointer stride -1");
  glFogCoordPointer(GL_FLOAT, -1, data);
  err("fog coord pointer stride -1");
  glSecondaryColorPointerEXT(4, GL_UNSIGNED_BYTE, 8, data);
  glFogCoordPointerEXT(GL_DOUBLE, 16, data + 2);
  ints("secondary array size", GL_SECONDARY_COLOR_ARRAY_SIZE);
  ints("secondary array type", GL_SECONDARY_COLOR_ARRAY_TYPE);
  ints("secondary array stride", GL_SECONDARY_COLOR_ARRAY_STRIDE);
  ints("fog coord array type", GL_FOG_COORD_ARRAY_TYPE);
  ints("fog coord array stride", GL_FOG_COORD_ARRAY_STRIDE);
  void *p;
  glGetPointerv(GL_SECONDARY_COLOR_ARRAY_POINTER, &p);
  printf("secondary pointer at %d\n", (int)((char *)p - (char *)data));
  glGetPointerv(GL_FOG_COORD_ARRAY_POINTER, &p);
  printf("fog coord pointer at %d\n", (int)((char *)p - (char *)data));
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glEnableClientState(GL_FOG_COORDINATE_ARRAY);
  ints("secondary array on", GL_SECONDARY_COLOR_ARRAY);
  printf("fog coord array is enabled %d\n", glIsEnabled(GL_FOG_COORD_ARRAY));
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
  glFogCoordPointer(GL_FLOAT, 4, data);
  glPopClientAttrib();
  ints("pop client secondary on", GL_SECONDARY_COLOR_ARRAY);
  ints("pop client fog type", GL_FOG_COORD_ARRAY_TYPE);
  glInterleavedArrays(GL_C3F_V3F, 0, data);
  ints("interleaved secondary on", GL_SECONDARY_COLOR_ARRAY);
  ints("interleaved fog coord on", GL_FOG_COORD_ARRAY);
  glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
  glDisableClientState(GL_FOG_COORD_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);

  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, 64, NULL, GL_STATIC_DRAW);
  glSecondaryColorPointer(3, GL_FLOAT, 0, (void *)12);
  glFogCoordPointer(GL_FLOAT, 0, (void *)4);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  ints("secondary buffer binding", GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING);
  ints("fog coord buffer binding", GL_FOG_COORD_ARRAY_BUFFER_BINDING);
  glDeleteBuffers(1, &b);
  ints("secondary binding deleted", GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING);

  /* The current values inside glBegin/glEnd, through glArrayElement and lists. */
  glBegin(GL_POINTS);
  glSecondaryColor3ubvEXT((GLubyte[]){51, 102, 153});
  glFogCoordfv((GLfloat[]){4});
  glEnd();
  err("inside glBegin");
  f4("secondary after pair", GL_CURRENT_SECONDARY_COLOR);
  f4("fog coord after pair", GL_CURRENT_FOG_COORD);
  GLubyte sc[8] = {255, 0, 0, 9, 0, 255, 0, 200};
  GLfloat fogs[2] = {1.5f, -6};
  glSecondaryColorPointer(4, GL_UNSIGNED_BYTE, 0, sc);
  glFogCoordPointer(GL_FLOAT, 0, fogs);
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glEnableClientState(GL_FOG_COORD_ARRAY);
  glArrayElement(1);
  f4("secondary after element", GL_CURRENT_SECONDARY_COLOR);
  f4("fog coord after element", GL_CURRENT_FOG_COORD);
  glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
  glDisableClientState(GL_FOG_COORD_ARRAY);
  glNewList(1, GL_COMPILE);
  glSecondaryColor3f(0.1f, 0.2f, 0.3f);
  glFogCoordd(7);
  glEndList();
  f4("secondary after compile", GL_CURRENT_SECONDARY_COLOR);
  glCallList(1);
  f4("secondary after list", GL_CURRENT_SECONDARY_COLOR);
  f4("fog coord after list", GL_CURRENT_FOG_COORD);
  glPushAttrib(GL_CURRENT_BIT);
  glSecondaryColor3f(1, 1, 1);
  glFogCoordf(9);
  glPopAttrib();
  f4("pop current secondary", GL_CURRENT_SECONDARY_COLOR);
  f4("pop current fog coord", GL_CURRENT_FOG_COORD);
  glPushAttrib(GL_FOG_BIT);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glPopAttrib();
  ints("pop fog src", GL_FOG_COORD_SRC);

  /* The raster distance under each source. */
  glFogCoordf(-5);
  glRasterPos3f(0, 0, -0.5f);
  f4("raster distance depth", GL_CURRENT_RASTER_DISTANCE);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glRasterPos3f(0, 0, -0.5f);
  f4("raster distance fog coord", GL_CURRENT_RASTER_DISTANCE);
  glWindowPos2i(3, 4);
  f4("window pos distance fog coord", GL_CURRENT_RASTER_DISTANCE);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glWindowPos2i(3, 4);
  f4("window pos distance depth", GL_CURRENT_RASTER_DISTANCE);
  glFogCoordf(0);
  glSecondaryColor3f(0, 0, 0);
}

static void linear_fog(float start, float end) {
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, start);
  glFogf(GL_FOG_END, end);
  glFogfv(GL_FOG_COLOR, (GLfloat[]){0.9f, 0.9f, 1, 1});
}

static void panels(void) {
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  /* 8: glBitmap adds the current secondary colour under COLOR_SUM; glDrawPixels does not.
   * Drawn first: after a glBegin/glEnd that set secondary colours, Mesa 22.3's glBitmap
   * adds none until some later state change (a stale current value, not followed). */
  panel(8);
  glEnable(GL_COLOR_SUM);
  {
    GLubyte bits[32] = {0}; /* eight rows of one byte, each padded to four */
    for (int i = 0; i < 8; i++) bits[4 * i] = (GLubyte)(0xA5 ^ (i * 0x11));
    GLubyte img[4 * 36];
    for (int i = 0; i < 36; i++) {
      img[4 * i] = (GLubyte)(40 + 5 * i);
      img[4 * i + 1] = 40;
      img[4 * i + 2] = 40;
      img[4 * i + 3] = 255;
    }
    glColor3f(0.5f, 0, 0);
    glSecondaryColor3f(0, 0.3f, 0);
    glRasterPos2f(-0.8f, -0.8f);
    glSecondaryColor3f(0, 0, 0.8f);
    glBitmap(8, 8, 0, 0, 0, 0, bits);
    glRasterPos2f(0.1f, 0.1f);
    glDrawPixels(6, 6, GL_RGBA, GL_UNSIGNED_BYTE, img);
  }
  glDisable(GL_COLOR_SUM);
  glSecondaryColor3f(0, 0, 0);
  /* 0: smooth unlit triangle, the sum of two colours per vertex. */
  panel(0);
  glEnable(GL_COLOR_SUM);
  glBegin(GL_TRIANGLES);
  glColor3f(0.5f, 0, 0); glSecondaryColor3f(0, 0.5f, 0); glVertex2f(-0.9f, -0.9f);
  glColor3f(0, 0.3f, 0); glSecondaryColor3f(0, 0, 0.8f); glVertex2f(0.9f, -0.9f);
  glColor3f(0, 0, 0.4f); glSecondaryColor3f(0.7f, 0.7f, 0); glVertex2f(0, 0.9f);
  glEnd();
  /* 1: flat quads and a polygon: the provoking vertex's secondary colour. */
  panel(1);
  glShadeModel(GL_FLAT);
  glColor3f(0.1f, 0.1f, 0.1f);
  glBegin(GL_QUADS);
  glSecondaryColor3f(1, 0, 0); glVertex2f(-0.9f, -0.9f);
  glSecondaryColor3f(0, 1, 0); glVertex2f(0, -0.9f);
  glSecondaryColor3f(0, 0, 1); glVertex2f(0, 0);
  glSecondaryColor3f(0.8f, 0.8f, 0); glVertex2f(-0.9f, 0);
  glEnd();
  glBegin(GL_POLYGON);
  glSecondaryColor3f(0, 0.6f, 0.6f); glVertex2f(0.1f, 0.1f);
  glSecondaryColor3f(0.6f, 0, 0.6f); glVertex2f(0.9f, 0.1f);
  glSecondaryColor3f(0.3f, 0.3f, 0.3f); glVertex2f(0.9f, 0.9f);
  glVertex2f(0.1f, 0.9f);
  glEnd();
  glShadeModel(GL_SMOOTH);
  /* 2: secondary colours from an array of unsigned bytes (size 4: alpha unused) and a
   * COLOR_SUM that is off for the right half. */
  panel(2);
  {
    GLfloat v[] = {-0.9f, -0.9f, 0, -0.9f, 0, 0.9f, -0.9f, 0.9f};
    GLubyte s[] = {255, 0, 0, 0, 0, 255, 0, 255, 0, 0, 255, 128, 255, 255, 255, 255};
    glColor4f(0, 0, 0, 1);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glSecondaryColorPointer(4, GL_UNSIGNED_BYTE, 0, s);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
    glDrawArrays(GL_QUADS, 0, 4);
    glTranslatef(0.95f, 0, 0);
    glDisable(GL_COLOR_SUM);
    glColor3f(0.2f, 0.2f, 0.6f);
    glDrawArrays(GL_QUADS, 0, 4);
    glLoadIdentity();
    glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glEnable(GL_COLOR_SUM);
  }
  /* 3: the sum after texturing (a modulated checker plus the secondary colour). */
  panel(3);
  {
    GLubyte tex[16] = {255, 255, 255, 255, 60, 60, 60, 255, 60, 60, 60, 255, 255, 255, 255, 255};
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    glEnable(GL_TEXTURE_2D);
    glColor3f(0.8f, 0.4f, 0.2f);
    glBegin(GL_QUADS);
    glSecondaryColor3f(0, 0, 0); glTexCoord2f(0, 0); glVertex2f(-0.9f, -0.9f);
    glSecondaryColor3f(0, 0, 0.9f); glTexCoord2f(1, 0); glVertex2f(0.9f, -0.9f);
    glTexCoord2f(1, 1); glVertex2f(0.9f, 0.9f);
    glSecondaryColor3f(0, 0, 0); glTexCoord2f(0, 1); glVertex2f(-0.9f, 0.9f);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &t);
  }
  glDisable(GL_COLOR_SUM);
  glSecondaryColor3f(0, 0, 0);
  /* 4: fog coordinates per vertex, LINEAR from 0 to 10; a negative coordinate fogs as
   * its magnitude, per vertex. */
  panel(4);
  linear_fog(0, 10);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glColor3f(0.8f, 0.1f, 0.1f);
  glBegin(GL_QUADS);
  glFogCoordf(0); glVertex2f(-0.9f, -0.9f);
  glFogCoordf(10); glVertex2f(0.9f, -0.9f);
  glFogCoordf(-10); glVertex2f(0.9f, 0);
  glFogCoordf(-3); glVertex2f(-0.9f, 0);
  glEnd();
  glBegin(GL_TRIANGLES);
  glFogCoordf(2); glVertex2f(-0.9f, 0.1f);
  glFogCoordf(8); glVertex2f(0.9f, 0.1f);
  glFogCoordf(-5); glVertex2f(0, 0.9f);
  glEnd();
  /* 5: fog coordinates from a buffer object, EXP2; then the same depth fogged by depth. */
  panel(5);
  {
    GLfloat v[] = {-0.9f, -0.9f, 0.9f, -0.9f, 0.9f, -0.05f, -0.9f, -0.05f};
    GLdouble f[] = {0.2, 1.5, 3, 0.7};
    GLuint b;
    glGenBuffers(1, &b);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBufferData(GL_ARRAY_BUFFER, sizeof f, f, GL_STATIC_DRAW);
    glFogCoordPointer(GL_DOUBLE, 0, 0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_FOG_COORD_ARRAY);
    glFogi(GL_FOG_MODE, GL_EXP2);
    glFogf(GL_FOG_DENSITY, 0.6f);
    glColor3f(0.1f, 0.7f, 0.2f);
    glDrawArrays(GL_QUADS, 0, 4);
    glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
    glTranslatef(0, 0.95f, 0);
    glDrawArrays(GL_QUADS, 0, 4);
    glLoadIdentity();
    glDisableClientState(GL_FOG_COORD_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDeleteBuffers(1, &b);
  }
  /* 6: a display list of a pair with secondary colours and fog coordinates, called twice
   * under different sources and sums. */
  panel(6);
  glNewList(2, GL_COMPILE);
  glBegin(GL_TRIANGLE_STRIP);
  glSecondaryColor3f(0, 0, 0.7f); glFogCoordf(1); glVertex2f(-0.9f, -0.9f);
  glSecondaryColor3f(0.7f, 0, 0); glFogCoordf(9); glVertex2f(0.9f, -0.9f);
  glSecondaryColor3f(0, 0.7f, 0); glFogCoordf(4); glVertex2f(-0.9f, 0);
  glSecondaryColor3f(0.5f, 0.5f, 0.5f); glFogCoordf(6); glVertex2f(0.9f, 0);
  glEnd();
  glEndList();
  linear_fog(0, 10);
  glColor3f(0.2f, 0.2f, 0.2f);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glCallList(2);
  glTranslatef(0, 0.95f, 0);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glDisable(GL_FOG);
  glEnable(GL_COLOR_SUM);
  glCallList(2);
  glLoadIdentity();
  /* 7: lines and points: a stippled line and wide points with secondary colours and fog
   * coordinates. */
  panel(7);
  linear_fog(0, 10);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glColor3f(0, 0, 0);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x5F5F);
  glLineWidth(2);
  glBegin(GL_LINES);
  glSecondaryColor3f(1, 0.5f, 0); glFogCoordf(0); glVertex2f(-0.9f, -0.7f);
  glSecondaryColor3f(0, 0.5f, 1); glFogCoordf(7); glVertex2f(0.9f, -0.2f);
  glEnd();
  glDisable(GL_LINE_STIPPLE);
  glLineWidth(1);
  glPointSize(4);
  glBegin(GL_POINTS);
  for (int i = 0; i < 5; i++) {
    glSecondaryColor3f(0.2f * (float)i, 1 - 0.2f * (float)i, 0.5f);
    glFogCoordf(2.0f * (float)i);
    glVertex2f(-0.8f + 0.4f * (float)i, 0.5f);
  }
  glEnd();
  glPointSize(1);
  glDisable(GL_FOG);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  /* 9: lit with SEPARATE_SPECULAR_COLOR, with and without COLOR_SUM: the secondary colour
   * is the specular term there, whatever glSecondaryColor says. */
  panel(9);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){0.3f, 0.4f, 1, 0});
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, (GLfloat[]){0.8f, 0.8f, 0.8f, 1});
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, (GLfloat[]){0.3f, 0.1f, 0.1f, 1});
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 8);
  glSecondaryColor3f(0, 0.9f, 0);
  glBegin(GL_TRIANGLES);
  glNormal3f(-0.5f, -0.5f, 0.7f); glVertex2f(-0.9f, -0.9f);
  glNormal3f(0.5f, -0.5f, 0.7f); glVertex2f(0.9f, -0.9f);
  glNormal3f(0, 0.6f, 0.8f); glVertex2f(0, 0.9f);
  glEnd();
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  glEnable(GL_COLOR_SUM);
  glTranslatef(0.5f, 0.5f, 0);
  glScalef(0.4f, 0.4f, 1);
  glBegin(GL_TRIANGLES);
  glNormal3f(-0.5f, -0.5f, 0.7f); glVertex2f(-0.9f, -0.9f);
  glNormal3f(0.5f, -0.5f, 0.7f); glVertex2f(0.9f, -0.9f);
  glNormal3f(0, 0.6f, 0.8f); glVertex2f(0, 0.9f);
  glEnd();
  glLoadIdentity();
  glDisable(GL_LIGHTING);
  glDisable(GL_COLOR_SUM);
  glSecondaryColor3f(0, 0, 0);
  /* 10: fog by depth and by coordinate side by side in perspective (EXP). */
  panel(10);
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_EXP);
  glFogf(GL_FOG_DENSITY, 0.25f);
  glColor3f(0.9f, 0.5f, 0.1f);
  for (int side = 0; side < 2; side++) {
    glFogi(GL_FOG_COORD_SRC, side ? GL_FOG_COORD : GL_FRAGMENT_DEPTH);
    float x0 = side ? 0.05f : -3, x1 = side ? 3 : -0.05f;
    glBegin(GL_QUADS);
    glFogCoordf(1); glVertex3f(x0, -3, -1.5f);
    glFogCoordf(1); glVertex3f(x1, -3, -1.5f);
    glFogCoordf(-6); glVertex3f(x1, 3, -8);
    glFogCoordf(-6); glVertex3f(x0, 3, -8);
    glEnd();
  }
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glDisable(GL_FOG);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glViewport(0, 0, W, H);
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "secondary.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  state_and_errors();
  panels();
  px("sum smooth", 12, 8);
  px("flat quad", 30, 6);
  px("flat polygon", 42, 18);
  px("array sum", 52, 6);
  px("array no sum", 64, 6);
  px("texture sum", 84, 6);
  px("fog coord quad", 12, 30);
  px("fog coord quad negative", 20, 35);
  px("bitmap sum", 5, 53);
  px("drawpixels no sum", 15, 63);
  glFinish();
  if (!write_ppm(out, buf, W, H)) return 1;
  OSMesaDestroyContext(ctx);
  free(buf);
  return 0;
}
