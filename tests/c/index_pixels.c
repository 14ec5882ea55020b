/* Colour-index data and state in an RGBA context, as programs of the 1990s used them: a
 * palette loaded into PIXEL_MAP_I_TO_R/G/B/A, then COLOR_INDEX images drawn with
 * glDrawPixels (UNSIGNED_BYTE, BYTE, SHORT, FLOAT, BITMAP) and uploaded with glTexImage2D
 * and glTexSubImage2D (the "palette through pixel maps" trick, with INDEX_SHIFT and
 * INDEX_OFFSET), each shown in a panel; then the material's COLOR_INDEXES, FOG_INDEX and
 * CURRENT_RASTER_INDEX with their attribute groups. Run on Mesa's OSMesa and on
 * fixedfunc's library, the printed lines must be the same and the images match.
 *
 * usage: index_pixels [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include "report.h"
#define W 64
#define H 32

/* The RGBA of `n` pixels of row y from x = 0. */
static void row(const char *what, int y, int n) {
  GLubyte out[4 * 16];
  glReadPixels(0, y, n, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  printf("%-22s", what);
  for (int k = 0; k < n; k++) printf(" %d,%d,%d,%d", out[4 * k], out[4 * k + 1], out[4 * k + 2], out[4 * k + 3]);
  printf("\n");
}

/* A texture of `n` texels read back, then drawn magnified over the panel at (x, y). */
static void texels(const char *what, int n, int x, int y) {
  GLubyte out[4 * 16] = {0};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  printf("%-22s", what);
  for (int k = 0; k < n; k++) printf(" %d,%d,%d,%d", out[4 * k], out[4 * k + 1], out[4 * k + 2], out[4 * k + 3]);
  printf("\n");
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0); glVertex2f(x, y);
  glTexCoord2f(1, 0); glVertex2f(x + 16, y);
  glTexCoord2f(1, 1); glVertex2f(x + 16, y + 16);
  glTexCoord2f(0, 1); glVertex2f(x, y + 16);
  glEnd();
  glDisable(GL_TEXTURE_2D);
}

static void material(const char *what, GLenum face) {
  GLfloat v[3] = {-7, -7, -7};
  GLint iv[3] = {-7, -7, -7};
  glGetMaterialfv(face, GL_COLOR_INDEXES, v);
  glGetMaterialiv(face, GL_COLOR_INDEXES, iv);
  printf("%-22s %.9g %.9g %.9g | %d %d %d err 0x%x\n", what, v[0], v[1], v[2], iv[0], iv[1], iv[2], glGetError());
}

static void fog_index(const char *what) {
  GLfloat f = -7;
  GLint i = -7;
  glGetFloatv(GL_FOG_INDEX, &f);
  glGetIntegerv(GL_FOG_INDEX, &i);
  printf("%-22s %.9g %d err 0x%x\n", what, f, i, glGetError());
}

int main(int argc, char **argv) {
  OSMesaContext ctx;
  GLubyte *buf = open_window(&ctx, W, H);
  if (!buf) return 1;
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);

  /* The palette: maps of 4, 4, 8 and 4 entries, an index masked to each map's size. */
  GLfloat r[4] = {0, 0.2f, 0.5f, 1}, g[4] = {1, 0.5f, 0.25f, 0.9f};
  GLfloat b[8] = {0.1f, 0.9f, 0.3f, 0.7f, 0.01f, 0.02f, 0.03f, 0.04f}, a[4] = {1, 0.5f, 0.6f, 0.7f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, r);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, g);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 8, b);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 4, a);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

  /* glDrawPixels, one row a type; no transfer applies to indices drawn. */
  GLubyte ub[6] = {0, 1, 2, 3, 5, 255};
  glRasterPos2i(0, 0);
  glDrawPixels(6, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ub);
  err("DrawPixels UNSIGNED_BYTE");
  row("UNSIGNED_BYTE", 0, 6);
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glRasterPos2i(0, 1);
  glDrawPixels(6, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ub);
  err("DrawPixels under transfer");
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferf(GL_RED_SCALE, 1);
  row("under transfer", 1, 6);
  GLbyte sb[6] = {-1, -2, -3, -4, 127, -128};
  glRasterPos2i(0, 2);
  glDrawPixels(6, 1, GL_COLOR_INDEX, GL_BYTE, sb);
  err("DrawPixels BYTE");
  row("BYTE", 2, 6);
  GLshort ss[6] = {-1, 258, 3, 7, 1025, -32768};
  glRasterPos2i(0, 3);
  glDrawPixels(6, 1, GL_COLOR_INDEX, GL_SHORT, ss);
  err("DrawPixels SHORT");
  row("SHORT", 3, 6);
  GLfloat fl[6] = {0.4f, 1.7f, 2.5f, -1, 6.99f, -2.5f};
  glRasterPos2i(0, 4);
  glDrawPixels(6, 1, GL_COLOR_INDEX, GL_FLOAT, fl);
  err("DrawPixels FLOAT");
  row("FLOAT", 4, 6);
  GLubyte bits[2] = {0xc4, 0x5b};
  glRasterPos2i(0, 5);
  glDrawPixels(5, 2, GL_COLOR_INDEX, GL_BITMAP, bits);
  err("DrawPixels BITMAP 5x2");
  row("BITMAP row 0", 5, 5);
  row("BITMAP row 1", 6, 5);
  /* Rows at alignment 4: Mesa reads the image as one run of its 3·2 indices. */
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  GLubyte al[8] = {1, 2, 3, 99, 0, 1, 2, 99};
  glRasterPos2i(0, 7);
  glDrawPixels(3, 2, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, al);
  err("DrawPixels at alignment 4");
  row("alignment 4 row 0", 7, 3);
  row("alignment 4 row 1", 8, 3);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  /* Zoomed, as a palette image is shown. */
  glPixelZoom(4, 4);
  glRasterPos2i(0, 12);
  glDrawPixels(6, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ub);
  glPixelZoom(1, 1);
  glDrawPixels(1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE_3_3_2, ub);
  err("DrawPixels packed type");
  glDrawPixels(1, 1, GL_RGBA, GL_BITMAP, ub);
  err("DrawPixels RGBA BITMAP");
  glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, GL_BITMAP, ub);
  err("ReadPixels COLOR_INDEX BITMAP");

  /* Texture images: shift and offset apply, scale and MAP_COLOR do not. */
  replace_texture();
  GLubyte ci[4] = {0, 1, 2, 3};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ci);
  err("TexImage2D UNSIGNED_BYTE");
  texels("texture", 4, 32, 0);
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  glPixelTransferf(GL_GREEN_BIAS, 0.25f);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ci);
  err("TexImage2D shifted");
  glPixelTransferi(GL_INDEX_SHIFT, -1);
  glPixelTransferi(GL_INDEX_OFFSET, -1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ci + 2);
  err("TexSubImage2D shifted");
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  glPixelTransferf(GL_GREEN_BIAS, 0);
  texels("shifted", 4, 48, 0);
  GLubyte tb[2] = {0xc4, 0x5b};
  glPixelStorei(GL_UNPACK_LSB_FIRST, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_COLOR_INDEX, GL_BITMAP, tb);
  glPixelStorei(GL_UNPACK_LSB_FIRST, 0);
  err("TexImage2D BITMAP");
  texels("BITMAP", 16, 32, 16);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 2, 2, 0, GL_COLOR_INDEX, GL_FLOAT, fl);
  err("TexImage2D FLOAT into LA");
  texels("FLOAT into LA", 4, 48, 16);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ci);
  err("TexImage2D into DEPTH");

  /* Colour-index state: material indexes, the fog index, the raster index. */
  material("default", GL_FRONT);
  GLfloat mi[3] = {1.5f, 2.7f, -3.2f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_COLOR_INDEXES, mi);
  err("Materialfv COLOR_INDEXES");
  material("front", GL_FRONT);
  GLint mii[3] = {4, 5, 6};
  glMaterialiv(GL_BACK, GL_COLOR_INDEXES, mii);
  err("Materialiv COLOR_INDEXES");
  material("back", GL_BACK);
  glPushAttrib(GL_LIGHTING_BIT);
  GLfloat zero[3] = {0, 0, 0};
  glMaterialfv(GL_FRONT, GL_COLOR_INDEXES, zero);
  material("pushed", GL_FRONT);
  glPopAttrib();
  material("popped", GL_FRONT);
  glBegin(GL_POINTS);
  GLfloat q[3] = {7, 8, 9};
  glMaterialfv(GL_FRONT, GL_COLOR_INDEXES, q);
  glVertex2f(1, 30);
  glEnd();
  err("inside glBegin/glEnd");
  material("after glEnd", GL_FRONT);
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  GLfloat q2[3] = {10, 11, 12};
  glMaterialfv(GL_BACK, GL_COLOR_INDEXES, q2);
  glFogf(GL_FOG_INDEX, 4.5f);
  glEndList();
  material("compiled", GL_BACK);
  fog_index("compiled");
  glCallList(list);
  material("called", GL_BACK);
  fog_index("called");
  glFogf(GL_FOG_INDEX, 2.6f);
  err("Fogf FOG_INDEX");
  fog_index("FOG_INDEX 2.6");
  glFogi(GL_FOG_INDEX, 3);
  fog_index("FOG_INDEX 3");
  glFogf(GL_FOG_INDEX, -2.5f);
  fog_index("FOG_INDEX -2.5");
  glPushAttrib(GL_FOG_BIT);
  glFogf(GL_FOG_INDEX, 1);
  fog_index("pushed");
  glPopAttrib();
  fog_index("popped");
  ints("CURRENT_RASTER_INDEX", GL_CURRENT_RASTER_INDEX);
  glPushAttrib(GL_CURRENT_BIT);
  glRasterPos2i(3, 3);
  glPopAttrib();
  ints("raster index popped", GL_CURRENT_RASTER_INDEX);

  return finish(argc > 1 ? argv[1] : "index_pixels.ppm", ctx, buf, W, H);
}
