/* Client-state calls between glBegin and glEnd: GL allows only the vertex attribute
 * calls, glArrayElement, glMaterial, glEvalCoord/Point, glCallList(s) and glEdgeFlag
 * there (GL 1.5 §2.6.3); every other call is INVALID_OPERATION and changes nothing.
 * Each line: the call made inside a pair, the error after glEnd, and the state it would
 * have changed. The outputs on Mesa's OSMesa and on fixedfunc's library must be the same.
 *
 * usage: begin_client */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>

static GLfloat va[32];

#define INSIDE(call)                                                  \
  do {                                                                \
    glBegin(GL_TRIANGLES);                                            \
    call;                                                             \
    glEnd();                                                          \
    printf("%-44s err 0x%x", #call, glGetError());                    \
  } while (0)

static void pointer(GLenum pname) {
  GLvoid *p = (GLvoid *)1;
  glGetPointerv(pname, &p);
  printf("  pointer set %d\n", p == (GLvoid *)va);
}

static void integer(GLenum pname) {
  GLint v = -1;
  glGetIntegerv(pname, &v);
  printf("  now 0x%x\n", v);
}

int main(void) {
  static GLubyte buffer[32 * 24 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 32, 24)) return 1;

  INSIDE(glListBase(7));
  integer(GL_LIST_BASE);
  INSIDE(glClientActiveTexture(GL_TEXTURE1));
  integer(GL_CLIENT_ACTIVE_TEXTURE);
  INSIDE(glVertexPointer(3, GL_FLOAT, 0, va));
  pointer(GL_VERTEX_ARRAY_POINTER);
  INSIDE(glNormalPointer(GL_FLOAT, 0, va));
  pointer(GL_NORMAL_ARRAY_POINTER);
  INSIDE(glColorPointer(3, GL_FLOAT, 0, va));
  pointer(GL_COLOR_ARRAY_POINTER);
  INSIDE(glTexCoordPointer(2, GL_FLOAT, 0, va));
  pointer(GL_TEXTURE_COORD_ARRAY_POINTER);
  INSIDE(glIndexPointer(GL_FLOAT, 0, va));
  pointer(GL_INDEX_ARRAY_POINTER);
  INSIDE(glEdgeFlagPointer(0, va));
  pointer(GL_EDGE_FLAG_ARRAY_POINTER);
  INSIDE(glFogCoordPointer(GL_FLOAT, 0, va));
  pointer(GL_FOG_COORD_ARRAY_POINTER);
  INSIDE(glSecondaryColorPointer(3, GL_FLOAT, 0, va));
  pointer(GL_SECONDARY_COLOR_ARRAY_POINTER);
  INSIDE(glInterleavedArrays(GL_V3F, 0, va));
  pointer(GL_VERTEX_ARRAY_POINTER);
  INSIDE(glEnableClientState(GL_NORMAL_ARRAY));
  printf("  enabled %d\n", glIsEnabled(GL_NORMAL_ARRAY));
  glEnableClientState(GL_COLOR_ARRAY);
  INSIDE(glDisableClientState(GL_COLOR_ARRAY));
  printf("  enabled %d\n", glIsEnabled(GL_COLOR_ARRAY));
  glDisableClientState(GL_COLOR_ARRAY);
  /* A bad argument inside the pair: the pair's error comes first. */
  INSIDE(glVertexPointer(7, GL_FLOAT, 0, va));
  printf("\n");
  INSIDE(glEnableClientState(GL_FOG));
  printf("\n");
  INSIDE(glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS));
  integer(GL_CLIENT_ATTRIB_STACK_DEPTH);
  INSIDE(glPopClientAttrib());
  integer(GL_CLIENT_ATTRIB_STACK_DEPTH);

  OSMesaDestroyContext(ctx);
  return 0;
}
