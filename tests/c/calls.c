/* The calls of GL 1.0–1.5 beyond the first ones: pixel storage, the client attribute
 * stack, glTexSubImage1D, glCopyTexImage1D, glCopyTexSubImage1D/2D and glGetTexImage, and
 * the integer and transposed variants (glLightiv, glLightModeliv, glMateriali/iv,
 * glTexEnviv, glTexParameteriv, glLoad/MultTransposeMatrix, glGetPointerv). Each check
 * prints one line (values, bytes, glGetError); the image is a framebuffer copy drawn back
 * as a texture.
 *
 * usage: calls OUT.ppm */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "gl_resolve.h"

#define W 128
#define H 128

static void report(const char *step) { printf("%-44s 0x%04x\n", step, (unsigned)glGetError()); }

static void integer(const char *name, GLenum pname) {
  GLint v[4] = {-7, -7, -7, -7};
  glGetIntegerv(pname, v);
  printf("%-44s %d\n", name, v[0]);
}

static void bytes(const char *name, const GLubyte *b, int n) {
  printf("%-44s", name);
  for (int i = 0; i < n; i++) printf(" %d", b[i]);
  printf("\n");
}

static void floats(const char *name, const GLfloat *f, int n) {
  printf("%-44s", name);
  for (int i = 0; i < n; i++) printf(" %.5f", f[i]);
  printf("\n");
}

static void pixel_store(void) {
  integer("initial GL_UNPACK_ALIGNMENT", GL_UNPACK_ALIGNMENT);
  integer("initial GL_PACK_ALIGNMENT", GL_PACK_ALIGNMENT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 3);
  report("glPixelStorei(UNPACK_ALIGNMENT, 3)");
  glPixelStoref(GL_PACK_ALIGNMENT, 2.0f);
  integer("glPixelStoref(PACK_ALIGNMENT, 2)", GL_PACK_ALIGNMENT);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  report("pixel storage");
}

static void client_attrib_stack(void) {
  static const GLfloat vertices[] = {0, 0, 1, 0, 0, 1};
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  integer("GL_MAX_CLIENT_ATTRIB_STACK_DEPTH", GL_MAX_CLIENT_ATTRIB_STACK_DEPTH);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  integer("depth after a push", GL_CLIENT_ATTRIB_STACK_DEPTH);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 8, vertices);
  glClientActiveTexture(GL_TEXTURE2);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(3, GL_SHORT, 0, vertices);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer);
  GLvoid *p = NULL;
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  printf("%-44s %d\n", "glGetPointerv is the vertex array", p == (GLvoid *)vertices);
  glGetPointerv(GL_COLOR_ARRAY_POINTER, &p);
  printf("%-44s %d\n", "glGetPointerv of an unset array is NULL", p == NULL);
  integer("GL_VERTEX_ARRAY_STRIDE inside", GL_VERTEX_ARRAY_STRIDE);
  integer("GL_CLIENT_ACTIVE_TEXTURE inside", GL_CLIENT_ACTIVE_TEXTURE);
  glPopClientAttrib();
  report("glPopClientAttrib (vertex arrays)");
  integer("GL_VERTEX_ARRAY after the pop", GL_VERTEX_ARRAY);
  integer("GL_VERTEX_ARRAY_SIZE after the pop", GL_VERTEX_ARRAY_SIZE);
  integer("GL_VERTEX_ARRAY_STRIDE after the pop", GL_VERTEX_ARRAY_STRIDE);
  integer("GL_CLIENT_ACTIVE_TEXTURE after the pop", GL_CLIENT_ACTIVE_TEXTURE);
  integer("GL_ARRAY_BUFFER_BINDING after the pop", GL_ARRAY_BUFFER_BINDING);
  integer("GL_ELEMENT_ARRAY_BUFFER_BINDING after the pop", GL_ELEMENT_ARRAY_BUFFER_BINDING);
  integer("GL_UNPACK_ALIGNMENT before the second pop", GL_UNPACK_ALIGNMENT);
  glPopClientAttrib();
  integer("GL_UNPACK_ALIGNMENT after the second pop", GL_UNPACK_ALIGNMENT);
  integer("GL_PACK_ALIGNMENT after the second pop", GL_PACK_ALIGNMENT);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glPopClientAttrib();
  report("glPopClientAttrib on an empty stack");
  for (int i = 0; i < 16; i++) glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  report("16 pushes");
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  report("the 17th push");
  integer("depth after the 17th push", GL_CLIENT_ATTRIB_STACK_DEPTH);
  for (int i = 0; i < 16; i++) glPopClientAttrib();
  /* Not compiled into a display list: the push runs at once. */
  glNewList(1, GL_COMPILE);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glEndList();
  integer("depth after a push inside glNewList", GL_CLIENT_ATTRIB_STACK_DEPTH);
  glCallList(1);
  integer("depth after glCallList", GL_CLIENT_ATTRIB_STACK_DEPTH);
  glPopClientAttrib();
  glBegin(GL_POINTS);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glEnd();
  report("glPushClientAttrib inside glBegin");
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, 16, NULL, GL_STATIC_DRAW);
  GLvoid *mapped = glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &p);
  printf("%-44s %d\n", "glGetBufferPointerv is the mapping", p == mapped && p != NULL);
  glUnmapBuffer(GL_ARRAY_BUFFER);
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &p);
  printf("%-44s %d\n", "glGetBufferPointerv unmapped is NULL", p == NULL);
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &p);
  report("glGetBufferPointerv(GL_BUFFER_SIZE)");
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glDeleteBuffers(1, &buffer);
}

static void variants(void) {
  GLfloat f[16];
  GLint iv[4];
  glLightiv(GL_LIGHT1, GL_AMBIENT, (GLint[]){INT_MAX, 0, INT_MAX / 2, -INT_MAX});
  glGetLightfv(GL_LIGHT1, GL_AMBIENT, f);
  floats("glLightiv ambient", f, 4);
  glLightiv(GL_LIGHT1, GL_POSITION, (GLint[]){1, 2, 3, 1});
  glGetLightfv(GL_LIGHT1, GL_POSITION, f);
  floats("glLightiv position", f, 4);
  glLightiv(GL_LIGHT1, GL_SPOT_CUTOFF, (GLint[]){45});
  glGetLightfv(GL_LIGHT1, GL_SPOT_CUTOFF, f);
  floats("glLightiv spot cutoff", f, 1);
  glLighti(GL_LIGHT1, GL_SPOT_EXPONENT, 7);
  glGetLightiv(GL_LIGHT1, GL_SPOT_EXPONENT, iv);
  printf("%-44s %d\n", "glLighti spot exponent", iv[0]);
  glLightiv(GL_LIGHT1, GL_SPOT_CUTOFF, (GLint[]){100});
  report("glLightiv cutoff 100");
  glLightModeliv(GL_LIGHT_MODEL_TWO_SIDE, (GLint[]){1});
  integer("glLightModeliv two side", GL_LIGHT_MODEL_TWO_SIDE);
  glLightModeliv(GL_LIGHT_MODEL_AMBIENT, (GLint[]){INT_MAX, 0, 0, INT_MAX});
  glGetFloatv(GL_LIGHT_MODEL_AMBIENT, f);
  floats("glLightModeliv ambient", f, 4);
  glLightModeliv(GL_LIGHT_MODEL_COLOR_CONTROL, (GLint[]){GL_SEPARATE_SPECULAR_COLOR});
  integer("glLightModeliv colour control", GL_LIGHT_MODEL_COLOR_CONTROL);
  glMateriali(GL_FRONT, GL_SHININESS, 20);
  glGetMaterialfv(GL_FRONT, GL_SHININESS, f);
  floats("glMateriali shininess", f, 1);
  glMaterialiv(GL_FRONT_AND_BACK, GL_DIFFUSE, (GLint[]){INT_MAX, 0, INT_MAX / 2, INT_MAX});
  glGetMaterialfv(GL_BACK, GL_DIFFUSE, f);
  floats("glMaterialiv diffuse", f, 4);
  /* Mesa: the scalar form takes a colour pname without an error (GL 1.5 allows
   * SHININESS only). Mesa then reads the colour's other components from beyond the
   * argument, so only the error is compared. */
  glMateriali(GL_FRONT, GL_DIFFUSE, 3);
  report("glMateriali(GL_DIFFUSE)");
  glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint[]){GL_ADD});
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, iv);
  printf("%-44s 0x%04x\n", "glTexEnviv mode", (unsigned)iv[0]);
  glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, (GLint[]){0, INT_MAX, 0, INT_MAX});
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, f);
  floats("glTexEnviv colour", f, 4);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLfloat[]){GL_MODULATE});
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, iv);
  printf("%-44s 0x%04x\n", "glTexEnvfv mode", (unsigned)iv[0]);
  glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint[]){GL_NEAREST});
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, iv);
  printf("%-44s 0x%04x\n", "glTexParameteriv min filter", (unsigned)iv[0]);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLfloat[]){GL_CLAMP_TO_EDGE});
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, iv);
  printf("%-44s 0x%04x\n", "glTexParameterfv wrap s", (unsigned)iv[0]);
  glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, (GLint[]){INT_MAX, 0, 0, 0});
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, f);
  floats("glTexParameteriv border colour", f, 4);
  glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint[]){GL_LINEAR_MIPMAP_LINEAR});
  report("glTexParameteriv mag filter mipmap");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR);
  GLint wrap_r = 0, resident = 0;
  GLfloat priority = 0, bias = -1;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R, &wrap_r);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_RESIDENT, &resident);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &priority);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, &bias);
  printf("%-44s 0x%04x %d %.5f %.5f\n", "wrap r, resident, priority, lod bias", (unsigned)wrap_r,
         resident, priority, bias);
  report("glGetTexParameter of the defaults");

  static const GLfloat rows[16] = {1, 0, 0, 5, 0, 2, 0, 6, 0, 0, 3, 7, 0, 0, 0, 1};
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadTransposeMatrixf(rows);
  glGetFloatv(GL_MODELVIEW_MATRIX, f);
  floats("glLoadTransposeMatrixf column 3", f + 12, 4);
  glMultTransposeMatrixd((GLdouble[]){1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1});
  glGetFloatv(GL_MODELVIEW_MATRIX, f);
  floats("glMultTransposeMatrixd column 3", f + 12, 4);
  glLoadTransposeMatrixdARB((GLdouble[]){2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 9, 0, 0, 0, 1});
  glMultTransposeMatrixfARB(rows);
  glGetFloatv(GL_MODELVIEW_MATRIX, f);
  floats("ARB transposes column 3", f + 12, 4);
  floats("ARB transposes column 0", f, 4);
  glLoadIdentity();
  glPopMatrix();
  report("variants");
}

static void get_tex_image(void) {
  GLubyte out[64];
  GLuint names[3];
  glGenTextures(3, names);
  glBindTexture(GL_TEXTURE_2D, names[0]);
  /* 3×2 luminance texels, rows packed (alignment 1). */
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE8, 3, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE,
               (GLubyte[]){10, 20, 30, 40, 50, 60});
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  memset(out, 0xee, sizeof out);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, out);
  bytes("LUMINANCE8 as LUMINANCE, pack alignment 4", out, 8);
  memset(out, 0xee, sizeof out);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  bytes("LUMINANCE8 as RGBA", out, 24);
  /* Rows of 4 texels, padded to 4 bytes already: alignment 4 reads them as given. */
  glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA8, 2, 2, 0, GL_ALPHA, GL_UNSIGNED_BYTE,
               (GLubyte[]){1, 2, 0, 0, 3, 4, 0, 0});
  memset(out, 0xee, sizeof out);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  bytes("ALPHA8 as RGBA", out, 16);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE8_ALPHA8, 2, 1, 0, GL_LUMINANCE_ALPHA,
               GL_UNSIGNED_BYTE, (GLubyte[]){100, 200, 7, 9});
  GLushort wide[8];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT, wide);
  printf("%-44s %u %u %u %u\n", "LUMINANCE8_ALPHA8 as UNSIGNED_SHORT", wide[0], wide[1],
         wide[2], wide[3]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               (GLubyte[]){10, 20, 30, 40, 50, 60, 70, 80});
  memset(out, 0xee, sizeof out);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, out);
  bytes("RGBA8 as LUMINANCE", out, 3);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE, out);
  bytes("RGBA8 as RGB", out, 6);
  GLfloat f[4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, f);
  floats("RGBA8 as FLOAT", f, 4);
  memset(out, 0xee, sizeof out);
  glGetTexImage(GL_TEXTURE_2D, 3, GL_RGBA, GL_UNSIGNED_BYTE, out);
  report("glGetTexImage of an unspecified level");
  bytes("  which stores nothing", out, 4);
  glGetTexImage(GL_TEXTURE_2D, -1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  report("glGetTexImage level -1");
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, out);
  report("glGetTexImage DEPTH_COMPONENT of RGBA8");
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_BYTE + 100, out);
  report("glGetTexImage bad type");
  glGetTexImage(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  report("glGetTexImage GL_TEXTURE_CUBE_MAP");

  /* 1D: an image, a sub-image, a copy, a copied sub-row. */
  glBindTexture(GL_TEXTURE_1D, names[1]);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glTexSubImage1D(GL_TEXTURE_1D, 0, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE,
                  (GLubyte[]){1, 2, 3, 4, 5, 6, 7, 8});
  report("glTexSubImage1D");
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  bytes("after glTexSubImage1D, texels 1 and 2", out + 4, 8);
  glTexSubImage1D(GL_TEXTURE_1D, 0, 3, 2, GL_RGBA, GL_UNSIGNED_BYTE, out);
  report("glTexSubImage1D past the end");
  glTexSubImage1D(GL_TEXTURE_2D, 0, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  report("glTexSubImage1D(GL_TEXTURE_2D)");
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClear(GL_COLOR_BUFFER_BIT);
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGB8, 0, 0, 2, 0);
  report("glCopyTexImage1D");
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  bytes("copied row as RGBA", out, 8);
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_ALPHA8, 0, 0, 2, 0);
  glGetTexImage(GL_TEXTURE_1D, 0, GL_ALPHA, GL_UNSIGNED_BYTE, out);
  bytes("copied row as ALPHA8", out, 2);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 1, 0, 0, 1);
  report("glCopyTexSubImage1D");
  glGetTexImage(GL_TEXTURE_1D, 0, GL_ALPHA, GL_UNSIGNED_BYTE, out);
  bytes("after glCopyTexSubImage1D", out, 2);
  glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 2, 0, 0, 1);
  report("glCopyTexSubImage1D past the end");
  glCopyTexSubImage1D(GL_TEXTURE_1D, 1, 0, 0, 0, 1);
  report("glCopyTexSubImage1D of an unspecified level");
  glCopyTexSubImage2D(GL_TEXTURE_1D, 0, 0, 0, 0, 0, 1, 1);
  report("glCopyTexSubImage2D(GL_TEXTURE_1D)");
  glBindTexture(GL_TEXTURE_1D, 0);
  glDeleteTextures(2, names);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
}

/* The image: four coloured quadrants, copied into the middle of an 8×8 texture with
 * glCopyTexSubImage2D, drawn back over the whole buffer. */
static void copy_and_draw(void) {
  GLubyte out[8 * 8 * 4];
  glViewport(0, 0, W, H);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, W, 0, H, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_QUADS);
  const GLubyte colours[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}};
  for (int q = 0; q < 4; q++) {
    int x = (q % 2) * 2, y = (q / 2) * 2;
    glColor3ubv(colours[q]);
    glVertex2i(x, y);
    glVertex2i(x + 2, y);
    glVertex2i(x + 2, y + 2);
    glVertex2i(x, y + 2);
  }
  glEnd();
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  static GLubyte grey[8 * 8 * 4];
  memset(grey, 128, sizeof grey);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, grey);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 2, 2, 0, 0, 4, 4);
  report("glCopyTexSubImage2D");
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 6, 6, 0, 0, 4, 4);
  report("glCopyTexSubImage2D past the edge");
  glCopyTexSubImage2D(GL_TEXTURE_2D, 2, 0, 0, 0, 0, 1, 1);
  report("glCopyTexSubImage2D of an unspecified level");
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, -1, 1);
  report("glCopyTexSubImage2D negative width");
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  bytes("texel row 2", out + 8 * 4 * 2, 32);
  bytes("texel row 5", out + 8 * 4 * 5, 32);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2i(0, 0);
  glTexCoord2f(1, 0);
  glVertex2i(W, 0);
  glTexCoord2f(1, 1);
  glVertex2i(W, H);
  glTexCoord2f(0, 1);
  glVertex2i(0, H);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  report("drawn");
}

int main(int argc, char **argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s OUT.ppm\n", argv[0]);
    return 2;
  }
  static GLubyte buffer[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) return 1;
  resolve_gl();
  pixel_store();
  client_attrib_stack();
  variants();
  get_tex_image();
  copy_and_draw();
  glFinish();
  int ok = write_ppm(argv[1], buffer, W, H);
  OSMesaDestroyContext(ctx);
  return ok ? 0 : 1;
}
