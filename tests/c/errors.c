/* GL errors as the specification gives them, one line per check: the call, then what
 * glGetError returned after it. Run on Mesa's OSMesa and on fixedfunc's library, the two
 * outputs must be the same.
 *
 * usage: errors */
#include <stdio.h>
#include <GL/osmesa.h>

#define CHECK(call)                                            \
  do {                                                         \
    call;                                                      \
    printf("%-58s 0x%04x\n", #call, (unsigned)glGetError());   \
  } while (0)

int main(void) {
  static GLubyte buffer[16 * 16 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 16, 16)) return 1;
  GLfloat four[4] = {1, 0, 0, 1};

  CHECK(glEnable(0x1234));
  CHECK(glMatrixMode(GL_LIGHTING));
  CHECK(glLineWidth(-1.0f));
  CHECK(glPointSize(0.0f));
  CHECK(glClear(0x1));
  CHECK(glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT));
  CHECK(glPopMatrix());
  CHECK(glLightfv(GL_LIGHT0 + 9, GL_DIFFUSE, four));
  CHECK(glLightfv(GL_LIGHT0, GL_TEXTURE_2D, four));
  CHECK(glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 100.0f));
  CHECK(glMaterialf(GL_FRONT, GL_SHININESS, 200.0f));
  CHECK(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_RGBA));
  CHECK(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST));
  CHECK(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_LIGHTING));
  CHECK(glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_LINEAR));
  CHECK(glDepthFunc(GL_ZERO));
  CHECK(glStencilOp(GL_KEEP, GL_KEEP, GL_ADD));
  CHECK(glBlendFunc(GL_SRC_ALPHA, GL_SRC_ALPHA_SATURATE));
  CHECK(glViewport(0, 0, -1, 4));
  CHECK(glPixelStorei(GL_UNPACK_ALIGNMENT, 3));
  CHECK(glPixelStorei(GL_PACK_ALIGNMENT, 8));
  CHECK(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  CHECK(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  CHECK(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
  CHECK(glEnd());
  CHECK(glVertex2f(0.5f, 0.5f));
  CHECK(glBegin(GL_TRIANGLES); glEnable(GL_LIGHTING); glEnd());
  CHECK(glBegin(GL_TRIANGLES); glBegin(GL_POINTS); glEnd());
  CHECK(glBegin(0x1234));
  /* The first error sticks until read: INVALID_ENUM, then no error. */
  CHECK(glEnable(0x1234); glLineWidth(-1.0f));
  CHECK((void)0);
  /* 32 modelview matrices fit; the 33rd push overflows. */
  for (int i = 0; i < 31; i++) glPushMatrix();
  CHECK(glPushMatrix());
  for (int i = 0; i < 31; i++) glPopMatrix();
  CHECK(glPopMatrix());
  CHECK(glGetString(0x1234));
  /* The imaging subset links and is refused, as on Mesa. */
  CHECK(glHistogram(GL_HISTOGRAM, 16, GL_RGBA, GL_FALSE));
  CHECK(glResetMinmax(GL_MINMAX));
  /* EXT_compiled_vertex_array, resolved as programs of its era resolved it: the range is
   * checked before a held lock, a second lock and an unlock without one are refused, and
   * the client attrib stack keeps the lock. */
  PFNGLLOCKARRAYSEXTPROC lock = (PFNGLLOCKARRAYSEXTPROC)OSMesaGetProcAddress("glLockArraysEXT");
  PFNGLUNLOCKARRAYSEXTPROC unlock =
      (PFNGLUNLOCKARRAYSEXTPROC)OSMesaGetProcAddress("glUnlockArraysEXT");
  if (!lock || !unlock) return 3;
  GLint range[2];
#define LOCKED()                                                   \
  glGetIntegerv(GL_ARRAY_ELEMENT_LOCK_FIRST_EXT, range);           \
  glGetIntegerv(GL_ARRAY_ELEMENT_LOCK_COUNT_EXT, range + 1);       \
  printf("locked elements %d, %d\n", range[0], range[1])
  LOCKED();
  CHECK(lock(-1, 3));
  CHECK(lock(0, 0));
  CHECK(unlock());
  CHECK(lock(2, 5));
  CHECK(lock(1, 1));
  LOCKED();
  CHECK(glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT); unlock());
  LOCKED();
  CHECK(glPopClientAttrib());
  LOCKED();
  CHECK(glBegin(GL_POINTS); unlock(); glEnd());
  CHECK(glNewList(1, GL_COMPILE); unlock(); glEndList(); glCallList(1));
  LOCKED();
  /* A generated name is a texture object before its first bind (Mesa makes it at
   * glGenTextures): resident, though glIsTexture says no; 0 and a deleted name are not. */
  GLuint tex[2];
  GLboolean residences[2] = {7, 7};
  glGenTextures(2, tex);
  printf("resident, generated: %d\n", glAreTexturesResident(2, tex, residences));
  CHECK(printf("is texture: %d\n", glIsTexture(tex[0])));
  glDeleteTextures(1, tex);
  printf("resident, one deleted: %d\n", glAreTexturesResident(2, tex, residences));
  CHECK((void)0);
  printf("residences untouched: %d %d\n", residences[0], residences[1]);
  printf("vendor set: %d\n", glGetString(GL_VENDOR) != NULL);
  /* glNewList while a list is compiled: INVALID_OPERATION before its arguments are
   * looked at (a bad mode, name 0). */
  glNewList(5, GL_COMPILE);
  CHECK(glNewList(6, GL_BYTE));
  CHECK(glNewList(0, GL_COMPILE));
  CHECK(glEndList());
  /* No indices are read for a count of 0: no error for NULL. */
  CHECK(glDrawElements(GL_TRIANGLES, 0, GL_UNSIGNED_SHORT, NULL));
  CHECK(glDrawElements(GL_TRIANGLES, 0, GL_FLOAT, NULL));
  OSMesaDestroyContext(ctx);
  return 0;
}
