/* ARB_point_sprite as particle programs of the early 2000s used it: glEnable(POINT_SPRITE)
 * and glTexEnvi(POINT_SPRITE, COORD_REPLACE, TRUE) on the units that should span each
 * point with the whole texture. The state's rules (the value TRUE or FALSE only, converted
 * as C converts a float; per unit; glPopAttrib of POINT_BIT, ENABLE_BIT and TEXTURE_BIT;
 * display lists), then panels of sprites textured with an asymmetric 8×8 texture: both
 * coordinate origins, fractional centres, POINT_SMOOTH (a sprite stays square), a unit
 * that does not replace, two units of which one replaces, a texture matrix (replaced
 * coordinates bypass it), attenuated sizes, the points of glPolygonMode(POINT), and a
 * triangle under POINT_SPRITE (untouched). Run on Mesa's OSMesa and on fixedfunc's
 * library, the printed lines must be the same and the images match.
 *
 * usage: point_sprites [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 128
#define H 96

static void coord_replace(const char *what) {
  GLint i = -7;
  GLfloat f = -7;
  glGetTexEnviv(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, &i);
  glGetTexEnvfv(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, &f);
  printf("%-36s COORD_REPLACE %d %g err 0x%x\n", what, i, f, glGetError());
}

static void set_replace(const char *what, GLfloat value) {
  glTexEnvf(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, value);
  GLenum e = glGetError();
  GLint i = -7;
  glGetTexEnviv(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, &i);
  printf("%-36s err 0x%x reads %d\n", what, e, i);
}

static void enabled(const char *what) {
  GLboolean b = 9;
  glGetBooleanv(GL_POINT_SPRITE_ARB, &b);
  printf("%-36s POINT_SPRITE %d %d err 0x%x\n", what, glIsEnabled(GL_POINT_SPRITE_ARB), b,
         glGetError());
}

/* A panel's points: a row of three at fractional centres, in window units. */
static void row(float x, float y) {
  glBegin(GL_POINTS);
  glTexCoord2f(0.3f, 0.6f);
  glVertex2f(x + 6.0f, y);
  glVertex2f(x + 17.5f, y + 0.5f);
  glVertex2f(x + 29.25f, y + 0.75f);
  glEnd();
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "point_sprites.ppm";
  OSMesaContext ctx;
  GLubyte *buf = open_window(&ctx, W, H); /* glOrtho(0, W, 0, H): a unit is a pixel */
  if (!buf) return 1;
  printf("extension named %d\n", extension_named("GL_ARB_point_sprite"));

  enabled("initial");
  coord_replace("initial");
  set_replace("glTexEnvf 1", 1);
  set_replace("glTexEnvf 0.5 (FALSE)", 0.5f);
  set_replace("glTexEnvf 1.9 (TRUE)", 1.9f);
  set_replace("glTexEnvf 2", 2);
  set_replace("glTexEnvf -1", -1);
  set_replace("glTexEnvf -0.5 (FALSE)", -0.5f);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, 3);
  printf("glTexEnvi 3                          err 0x%x\n", glGetError());
  GLint iv[1] = {1};
  glTexEnviv(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, iv);
  coord_replace("glTexEnviv TRUE");
  GLfloat fv[1] = {0};
  glTexEnvfv(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, fv);
  coord_replace("glTexEnvfv FALSE");
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  printf("POINT_SPRITE, TEXTURE_ENV_MODE       err 0x%x\n", glGetError());
  glTexEnvi(GL_TEXTURE_ENV, GL_COORD_REPLACE_ARB, GL_TRUE);
  printf("TEXTURE_ENV, COORD_REPLACE           err 0x%x\n", glGetError());
  GLint i = -7;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_COORD_REPLACE_ARB, &i);
  printf("glGetTexEnv(TEXTURE_ENV, COORD_REPLACE) err 0x%x\n", glGetError());

  glActiveTexture(GL_TEXTURE1);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_TRUE);
  coord_replace("unit 1 set");
  glActiveTexture(GL_TEXTURE0);
  coord_replace("unit 0 then");
  glActiveTexture(GL_TEXTURE1);
  glPushAttrib(GL_POINT_BIT);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_FALSE);
  glEnable(GL_POINT_SPRITE_ARB);
  glPopAttrib();
  coord_replace("unit 1 after POINT_BIT");
  enabled("after POINT_BIT");
  glPushAttrib(GL_TEXTURE_BIT);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_FALSE);
  glPopAttrib();
  coord_replace("unit 1 after TEXTURE_BIT");
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_POINT_SPRITE_ARB);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_POINT_SPRITE_ARB);
  glPopAttrib();
  enabled("after ENABLE_BIT");
  glPushAttrib(GL_POINT_BIT);
  glDisable(GL_POINT_SPRITE_ARB);
  glPopAttrib();
  enabled("after POINT_BIT");
  glDisable(GL_POINT_SPRITE_ARB);
  glNewList(1, GL_COMPILE);
  glEnable(GL_POINT_SPRITE_ARB);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_TRUE);
  glEndList();
  enabled("list compiled");
  coord_replace("list compiled");
  glCallList(1);
  enabled("list called");
  coord_replace("list called");
  glBegin(GL_POINTS);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_TRUE);
  glEnd();
  printf("inside glBegin/glEnd                 err 0x%x\n", glGetError());
  glGetIntegerv(GL_POINT_SPRITE_COORD_ORIGIN, &i);
  printf("origin 0x%x err 0x%x\n", i, glGetError());

  /* The texture: s runs red 0 → 255 across, t green 0 → 255 up, a blue texel at (0, 0). */
  static GLubyte texels[8 * 8 * 4];
  for (int y = 0; y < 8; y++)
    for (int x = 0; x < 8; x++) {
      GLubyte *p = texels + 4 * (y * 8 + x);
      p[0] = (GLubyte)(x * 36);
      p[1] = (GLubyte)(y * 36);
      p[2] = (x == 0 && y == 0) ? 255 : 40;
      p[3] = 255;
    }
  GLuint tex[2];
  glGenTextures(2, tex);
  for (int u = 0; u < 2; u++) {
    glActiveTexture(GL_TEXTURE0 + u);
    glBindTexture(GL_TEXTURE_2D, tex[u]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_FALSE);
  }
  glActiveTexture(GL_TEXTURE0);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_POINT_SPRITE_ARB);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_TRUE);
  glPointSize(8);
  row(0, 88);                                          /* upper-left origin */
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  row(0, 76);                                          /* lower-left origin */
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
  glEnable(GL_POINT_SMOOTH);
  glPointSize(9.5f);
  row(0, 62);                                          /* smooth: still square */
  glDisable(GL_POINT_SMOOTH);
  glPointSize(8);
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_FALSE);
  row(0, 48);                                          /* not replaced: one texel */
  glTexEnvi(GL_POINT_SPRITE_ARB, GL_COORD_REPLACE_ARB, GL_TRUE);
  glMatrixMode(GL_TEXTURE);
  glScalef(0.25f, 0.25f, 1);
  row(0, 36);                                          /* the texture matrix bypassed */
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);

  /* Two units: unit 0 replaces, unit 1 reads the vertex's coordinates, modulated. */
  glActiveTexture(GL_TEXTURE1);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glActiveTexture(GL_TEXTURE0);
  glBegin(GL_POINTS);
  glMultiTexCoord2f(GL_TEXTURE1, 0.9f, 0.9f);
  glVertex2f(6, 22);
  glMultiTexCoord2f(GL_TEXTURE1, 0.5f, 0.1f);
  glVertex2f(18, 22);
  glEnd();
  glActiveTexture(GL_TEXTURE1);
  glDisable(GL_TEXTURE_2D);
  glActiveTexture(GL_TEXTURE0);

  /* Sizes attenuated by distance, in perspective. */
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glFrustum(-1, 1, -0.75, 0.75, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  GLfloat attenuation[3] = {0, 0.4f, 0};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
  glPointSize(16);
  glBegin(GL_POINTS);
  for (int k = 0; k < 4; k++) {
    float z = -1.5f - 1.2f * (float)k;
    glVertex3f((0.15f + 0.22f * (float)k) * -z, 0.55f * -z, z);
  }
  glEnd();
  GLfloat none[3] = {1, 0, 0};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);

  /* The corners of a triangle drawn as points (glPolygonMode), then a filled triangle. */
  glPointSize(6);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glBegin(GL_TRIANGLES);
  glTexCoord2f(0.1f, 0.1f);
  glVertex3f(0.1f, -0.2f, -2);
  glVertex3f(0.6f, -0.2f, -2);
  glVertex3f(0.35f, 0.2f, -2);
  glEnd();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glBegin(GL_TRIANGLES);
  glTexCoord2f(0, 0);
  glVertex3f(0.9f, -0.6f, -2);
  glTexCoord2f(1, 0);
  glVertex3f(1.6f, -0.6f, -2);
  glTexCoord2f(0.5f, 1);
  glVertex3f(1.25f, 0.1f, -2);
  glEnd();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);

  glFinish();
  printf("draw err 0x%x\n", glGetError());
  return finish(out, ctx, buf, W, H);
}
