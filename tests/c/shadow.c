/* A shadow-mapping program in the style of 2000–2005, loading OSMesa at run time: it
 * dlopen()s libOSMesa.so.8, resolves every GL function through OSMesaGetProcAddress, and
 * draws four panels of one scene (a box above a ground), each through another geometry
 * path — immediate mode, client arrays, a display list, buffer objects — with the light
 * pass drawn into the main buffer and copied with glCopyTexImage2D (panels 0 and 2) or
 * drawn into a depth texture through a framebuffer object (panels 1 and 3). The eye pass
 * projects the map with eye-linear texgen and the texture matrix, compares with
 * ARB_shadow, modulates by texture combine, and tints the box through the stencil buffer.
 * Polygon offset biases the light pass. glReadPixels reads a lit and a shadowed pixel of
 * each panel. Run on Mesa's OSMesa and on fixedfunc's library, the printed lines must be
 * the same and the images match.
 *
 * usage: shadow [out.ppm] */
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define W 128
#define H 128
#define P 64   /* a panel's side */
#define MAP 64 /* the shadow map's side */

/* Every GL function the program calls: (return type, name, parameters). */
#define GL_FUNCTIONS(X)                                                                \
  X(void, glViewport, (GLint, GLint, GLsizei, GLsizei))                                \
  X(void, glScissor, (GLint, GLint, GLsizei, GLsizei))                                 \
  X(void, glEnable, (GLenum))                                                          \
  X(void, glDisable, (GLenum))                                                         \
  X(void, glClearColor, (GLfloat, GLfloat, GLfloat, GLfloat))                          \
  X(void, glClear, (GLbitfield))                                                       \
  X(void, glMatrixMode, (GLenum))                                                      \
  X(void, glLoadIdentity, (void))                                                      \
  X(void, glMultMatrixf, (const GLfloat *))                                            \
  X(void, glLoadMatrixf, (const GLfloat *))                                            \
  X(void, glFrustum, (GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble))     \
  X(void, glTranslatef, (GLfloat, GLfloat, GLfloat))                                   \
  X(void, glScalef, (GLfloat, GLfloat, GLfloat))                                       \
  X(void, glColor3f, (GLfloat, GLfloat, GLfloat))                                      \
  X(void, glColor4f, (GLfloat, GLfloat, GLfloat, GLfloat))                             \
  X(void, glBegin, (GLenum))                                                           \
  X(void, glEnd, (void))                                                               \
  X(void, glVertex3fv, (const GLfloat *))                                              \
  X(void, glVertex2f, (GLfloat, GLfloat))                                              \
  X(void, glColorMask, (GLboolean, GLboolean, GLboolean, GLboolean))                   \
  X(void, glPolygonOffset, (GLfloat, GLfloat))                                         \
  X(void, glBindTexture, (GLenum, GLuint))                                             \
  X(void, glGenTextures, (GLsizei, GLuint *))                                          \
  X(void, glDeleteTextures, (GLsizei, const GLuint *))                                 \
  X(void, glTexImage2D, (GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum, \
                         const void *))                                                \
  X(void, glCopyTexImage2D, (GLenum, GLint, GLenum, GLint, GLint, GLsizei, GLsizei,     \
                             GLint))                                                   \
  X(void, glTexParameteri, (GLenum, GLenum, GLint))                                    \
  X(void, glTexGeni, (GLenum, GLenum, GLint))                                          \
  X(void, glTexGenfv, (GLenum, GLenum, const GLfloat *))                               \
  X(void, glTexEnvi, (GLenum, GLenum, GLint))                                          \
  X(void, glStencilFunc, (GLenum, GLint, GLuint))                                      \
  X(void, glStencilOp, (GLenum, GLenum, GLenum))                                       \
  X(void, glBlendFunc, (GLenum, GLenum))                                               \
  X(void, glReadPixels, (GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void *))       \
  X(void, glEnableClientState, (GLenum))                                               \
  X(void, glDisableClientState, (GLenum))                                              \
  X(void, glVertexPointer, (GLint, GLenum, GLsizei, const void *))                     \
  X(void, glDrawArrays, (GLenum, GLint, GLsizei))                                      \
  X(void, glDrawElements, (GLenum, GLsizei, GLenum, const void *))                     \
  X(GLuint, glGenLists, (GLsizei))                                                     \
  X(void, glNewList, (GLuint, GLenum))                                                 \
  X(void, glEndList, (void))                                                           \
  X(void, glCallList, (GLuint))                                                        \
  X(void, glDeleteLists, (GLuint, GLsizei))                                            \
  X(void, glGenBuffers, (GLsizei, GLuint *))                                           \
  X(void, glBindBuffer, (GLenum, GLuint))                                              \
  X(void, glBufferData, (GLenum, GLsizeiptr, const void *, GLenum))                    \
  X(void, glDeleteBuffers, (GLsizei, const GLuint *))                                  \
  X(void, glGenFramebuffersEXT, (GLsizei, GLuint *))                                   \
  X(void, glBindFramebufferEXT, (GLenum, GLuint))                                      \
  X(void, glFramebufferTexture2DEXT, (GLenum, GLenum, GLenum, GLuint, GLint))          \
  X(GLenum, glCheckFramebufferStatusEXT, (GLenum))                                     \
  X(void, glDeleteFramebuffersEXT, (GLsizei, const GLuint *))                          \
  X(void, glDrawBuffer, (GLenum))                                                      \
  X(void, glReadBuffer, (GLenum))                                                      \
  X(GLenum, glGetError, (void))                                                        \
  X(void, glFinish, (void))

#define DECLARE(ret, name, params) static ret(*p_##name) params;
GL_FUNCTIONS(DECLARE)

typedef OSMesaContext (*CreateContextExt)(GLenum, GLint, GLint, GLint, OSMesaContext);
typedef GLboolean (*MakeCurrent)(OSMesaContext, void *, GLenum, GLsizei, GLsizei);
typedef OSMESAproc (*GetProcAddress)(const char *);
typedef void (*DestroyContext)(OSMesaContext);

/* The scene: a ground square (y = 0) and a box above it, as quads. */
static const GLfloat ground[4][3] = {{-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2}};
static GLfloat box[24][3];

static void make_box(void) {
  const GLfloat lo[3] = {-0.5f, 0.8f, -0.5f}, hi[3] = {0.5f, 1.4f, 0.5f};
  static const int faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                  {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for (int f = 0; f < 6; f++)
    for (int k = 0; k < 4; k++) {
      int c = faces[f][k];
      box[4 * f + k][0] = (c & 4) ? hi[0] : lo[0];
      box[4 * f + k][1] = (c & 2) ? hi[1] : lo[1];
      box[4 * f + k][2] = (c & 1) ? hi[2] : lo[2];
    }
}

/* The same quads as triangles, by index (arrays and buffer objects). */
static GLushort tri_index[36];
static GLfloat all[28][3];

static void make_triangles(void) {
  for (int v = 0; v < 4; v++)
    for (int k = 0; k < 3; k++) all[v][k] = ground[v][k];
  for (int v = 0; v < 24; v++)
    for (int k = 0; k < 3; k++) all[4 + v][k] = box[v][k];
  for (int q = 0; q < 6; q++) {
    GLushort b = (GLushort)(4 + 4 * q);
    GLushort t[6] = {b, (GLushort)(b + 1), (GLushort)(b + 2), b, (GLushort)(b + 2),
                     (GLushort)(b + 3)};
    for (int k = 0; k < 6; k++) tri_index[6 * q + k] = t[k];
  }
}

/* gluLookAt's matrix, column-major. */
static void look_at(GLfloat m[16], const GLfloat eye[3], const GLfloat at[3]) {
  GLfloat f[3] = {at[0] - eye[0], at[1] - eye[1], at[2] - eye[2]};
  GLfloat n = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  for (int i = 0; i < 3; i++) f[i] /= n;
  GLfloat up[3] = {0, 1, 0};
  GLfloat s[3] = {f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2],
                  f[0] * up[1] - f[1] * up[0]};
  n = sqrtf(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  for (int i = 0; i < 3; i++) s[i] /= n;
  GLfloat u[3] = {s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2],
                  s[0] * f[1] - s[1] * f[0]};
  GLfloat r[16] = {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0,
                   s[2], u[2], -f[2], 0, 0,    0,    0,     1};
  for (int i = 0; i < 16; i++) m[i] = r[i];
  m[12] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
  m[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
  m[14] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
}

static const GLfloat light_eye[3] = {-2, 4, -2.5f}, camera_eye[3] = {0, 3, 4.5f};
static const GLfloat origin[3] = {0, 0, 0};
static GLfloat light_view[16], camera_view[16];

static void light_projection(void) { p_glFrustum(-0.5, 0.5, -0.5, 0.5, 1.5, 10); }
static void camera_projection(void) { p_glFrustum(-0.4, 0.4, -0.4, 0.4, 1, 12); }

enum Path { IMMEDIATE, ARRAYS, LIST, BUFFERS };
static GLuint list, vbo[2];

/* The scene's geometry through `path`; the box is drawn with stencil reference 1. */
static void draw_scene(enum Path path, int colored) {
  if (colored) p_glColor3f(0.8f, 0.8f, 0.7f);
  p_glStencilFunc(GL_ALWAYS, 0, 0xff);
  switch (path) {
  case IMMEDIATE:
    p_glBegin(GL_QUADS);
    for (int v = 0; v < 4; v++) p_glVertex3fv(ground[v]);
    p_glEnd();
    if (colored) p_glColor3f(0.9f, 0.5f, 0.2f);
    p_glStencilFunc(GL_ALWAYS, 1, 0xff);
    p_glBegin(GL_QUADS);
    for (int v = 0; v < 24; v++) p_glVertex3fv(box[v]);
    p_glEnd();
    break;
  case ARRAYS:
    p_glEnableClientState(GL_VERTEX_ARRAY);
    p_glVertexPointer(3, GL_FLOAT, 0, all);
    p_glDrawArrays(GL_QUADS, 0, 4);
    if (colored) p_glColor3f(0.9f, 0.5f, 0.2f);
    p_glStencilFunc(GL_ALWAYS, 1, 0xff);
    p_glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_SHORT, tri_index);
    p_glDisableClientState(GL_VERTEX_ARRAY);
    break;
  case LIST:
    /* The list holds the ground; the box's colour and stencil come around it. */
    p_glCallList(list);
    if (colored) p_glColor3f(0.9f, 0.5f, 0.2f);
    p_glStencilFunc(GL_ALWAYS, 1, 0xff);
    p_glCallList(list + 1);
    break;
  case BUFFERS:
    p_glBindBuffer(GL_ARRAY_BUFFER, vbo[0]);
    p_glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, vbo[1]);
    p_glEnableClientState(GL_VERTEX_ARRAY);
    p_glVertexPointer(3, GL_FLOAT, 0, (const void *)0);
    p_glDrawArrays(GL_QUADS, 0, 4);
    if (colored) p_glColor3f(0.9f, 0.5f, 0.2f);
    p_glStencilFunc(GL_ALWAYS, 1, 0xff);
    p_glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_SHORT, (const void *)0);
    p_glDisableClientState(GL_VERTEX_ARRAY);
    p_glBindBuffer(GL_ARRAY_BUFFER, 0);
    p_glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    break;
  }
}

/* The light's depth into `map`: drawn into the panel's corner of the main buffer and
 * copied (use_fbo 0), or drawn into the texture through `fbo`. */
static void light_pass(enum Path path, int x, int y, GLuint map, GLuint fbo, int use_fbo) {
  if (use_fbo) {
    p_glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fbo);
    p_glViewport(0, 0, MAP, MAP);
  } else {
    p_glViewport(x, y, MAP, MAP);
    p_glScissor(x, y, MAP, MAP);
    p_glEnable(GL_SCISSOR_TEST);
  }
  p_glEnable(GL_DEPTH_TEST);
  p_glClear(GL_DEPTH_BUFFER_BIT);
  p_glMatrixMode(GL_PROJECTION);
  p_glLoadIdentity();
  light_projection();
  p_glMatrixMode(GL_MODELVIEW);
  p_glLoadMatrixf(light_view);
  p_glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  p_glEnable(GL_POLYGON_OFFSET_FILL);
  p_glPolygonOffset(1.1f, 4);
  draw_scene(path, 0);
  p_glDisable(GL_POLYGON_OFFSET_FILL);
  p_glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (use_fbo) {
    p_glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
  } else {
    p_glBindTexture(GL_TEXTURE_2D, map);
    p_glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, x, y, MAP, MAP, 0);
    p_glDisable(GL_SCISSOR_TEST);
  }
}

/* The eye pass of one panel: the camera's view of the scene, lit where the map's depth
 * is not nearer than the fragment's (ARB_shadow), the box tinted through the stencil. */
static void eye_pass(enum Path path, int x, int y, GLuint map) {
  static const GLfloat planes[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  static const GLenum coords[4] = {GL_S, GL_T, GL_R, GL_Q};
  static const GLenum gens[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
                                 GL_TEXTURE_GEN_Q};
  p_glViewport(x, y, P, P);
  p_glScissor(x, y, P, P);
  p_glEnable(GL_SCISSOR_TEST);
  p_glClearColor(0.15f, 0.15f, 0.3f, 1);
  p_glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  p_glMatrixMode(GL_PROJECTION);
  p_glLoadIdentity();
  camera_projection();
  p_glMatrixMode(GL_MODELVIEW);
  p_glLoadMatrixf(camera_view);
  /* Eye planes given under the camera's view: the generated (s, t, r, q) are world
   * coordinates, which the texture matrix takes into the light's window space. */
  for (int i = 0; i < 4; i++) {
    p_glTexGeni(coords[i], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    p_glTexGenfv(coords[i], GL_EYE_PLANE, planes[i]);
    p_glEnable(gens[i]);
  }
  p_glMatrixMode(GL_TEXTURE);
  p_glLoadIdentity();
  p_glTranslatef(0.5f, 0.5f, 0.5f);
  p_glScalef(0.5f, 0.5f, 0.5f);
  light_projection();
  p_glMultMatrixf(light_view);
  p_glMatrixMode(GL_MODELVIEW);
  p_glBindTexture(GL_TEXTURE_2D, map);
  p_glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  p_glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  p_glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  p_glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  p_glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE_ARB, GL_COMPARE_R_TO_TEXTURE_ARB);
  p_glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC_ARB, GL_LEQUAL);
  /* Lit = colour; shadowed = colour × 0 + colour × 0.25 would need two units: the era's
   * one-unit form modulates, and the dim term comes from the interpolated alpha. */
  p_glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  p_glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_MODULATE);
  p_glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_PRIMARY_COLOR);
  p_glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_SRC_COLOR);
  p_glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_TEXTURE);
  p_glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_SRC_COLOR);
  p_glEnable(GL_TEXTURE_2D);
  p_glEnable(GL_DEPTH_TEST);
  p_glEnable(GL_STENCIL_TEST);
  p_glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  draw_scene(path, 1);
  p_glDisable(GL_TEXTURE_2D);
  for (int i = 0; i < 4; i++) p_glDisable(gens[i]);
  p_glMatrixMode(GL_TEXTURE);
  p_glLoadIdentity();
  p_glMatrixMode(GL_MODELVIEW);
  /* Where the box was drawn, a translucent blue tint over the whole panel. */
  p_glDisable(GL_DEPTH_TEST);
  p_glStencilFunc(GL_EQUAL, 1, 0xff);
  p_glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  p_glEnable(GL_BLEND);
  p_glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  p_glMatrixMode(GL_PROJECTION);
  p_glLoadIdentity();
  p_glMatrixMode(GL_MODELVIEW);
  p_glLoadIdentity();
  p_glColor4f(0.2f, 0.4f, 1, 0.35f);
  p_glBegin(GL_QUADS);
  p_glVertex2f(-1, -1);
  p_glVertex2f(1, -1);
  p_glVertex2f(1, 1);
  p_glVertex2f(-1, 1);
  p_glEnd();
  p_glDisable(GL_BLEND);
  p_glDisable(GL_STENCIL_TEST);
  p_glDisable(GL_SCISSOR_TEST);
}

/* What a pixel shows: the lit ground, its shadow (black: the compare gave 0), the
 * tinted box, or something else. */
static const char *kind(const GLubyte *p) {
  if (p[0] > 150 && p[1] > 150) return "lit";
  if (p[0] + p[1] + p[2] < 30) return "shadow";
  if (p[2] > p[0] + 30) return "tinted";
  return "other";
}

int main(int argc, char **argv) {
  void *lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
  if (!lib) {
    fprintf(stderr, "dlopen: %s\n", dlerror());
    return 2;
  }
  CreateContextExt create = (CreateContextExt)dlsym(lib, "OSMesaCreateContextExt");
  MakeCurrent make_current = (MakeCurrent)dlsym(lib, "OSMesaMakeCurrent");
  GetProcAddress proc = (GetProcAddress)dlsym(lib, "OSMesaGetProcAddress");
  DestroyContext destroy = (DestroyContext)dlsym(lib, "OSMesaDestroyContext");
  if (!create || !make_current || !proc || !destroy) {
    fprintf(stderr, "the library lacks the OSMesa API\n");
    return 2;
  }
  static GLubyte buffer[W * H * 4];
  OSMesaContext ctx = create(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !make_current(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) return 1;
#define RESOLVE(ret, name, params)                                                  \
  p_##name = (ret(*) params)(void (*)(void))proc(#name);                            \
  if (!p_##name) {                                                                  \
    fprintf(stderr, "OSMesaGetProcAddress(\"%s\") returned NULL\n", #name);         \
    return 2;                                                                       \
  }
  GL_FUNCTIONS(RESOLVE)

  make_box();
  make_triangles();
  look_at(light_view, light_eye, origin);
  look_at(camera_view, camera_eye, origin);

  /* The display lists and buffer objects, made once. */
  list = p_glGenLists(2);
  p_glNewList(list, GL_COMPILE);
  p_glBegin(GL_QUADS);
  for (int v = 0; v < 4; v++) p_glVertex3fv(ground[v]);
  p_glEnd();
  p_glEndList();
  p_glNewList(list + 1, GL_COMPILE);
  p_glBegin(GL_QUADS);
  for (int v = 0; v < 24; v++) p_glVertex3fv(box[v]);
  p_glEnd();
  p_glEndList();
  p_glGenBuffers(2, vbo);
  p_glBindBuffer(GL_ARRAY_BUFFER, vbo[0]);
  p_glBufferData(GL_ARRAY_BUFFER, sizeof all, all, GL_STATIC_DRAW);
  p_glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, vbo[1]);
  p_glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof tri_index, tri_index, GL_STATIC_DRAW);
  p_glBindBuffer(GL_ARRAY_BUFFER, 0);
  p_glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  printf("%-36s err 0x%x\n", "lists and buffers made", p_glGetError());

  /* The maps: one copied from the main buffer, one drawn through a framebuffer. */
  GLuint maps[2], fbo;
  p_glGenTextures(2, maps);
  p_glBindTexture(GL_TEXTURE_2D, maps[1]);
  p_glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, MAP, MAP, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, NULL);
  p_glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  p_glGenFramebuffersEXT(1, &fbo);
  p_glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fbo);
  p_glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_TEXTURE_2D,
                              maps[1], 0);
  p_glDrawBuffer(GL_NONE);
  p_glReadBuffer(GL_NONE);
  printf("%-36s 0x%x  err 0x%x\n", "depth-only framebuffer",
         p_glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT), p_glGetError());
  p_glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);

  static const char *names[4] = {"immediate", "client arrays", "display list",
                                 "buffer objects"};
  for (int panel = 0; panel < 4; panel++) {
    int x = (panel % 2) * P, y = (panel / 2) * P;
    int use_fbo = panel % 2;
    GLuint map = maps[use_fbo];
    light_pass((enum Path)panel, x, y, map, fbo, use_fbo);
    eye_pass((enum Path)panel, x, y, map);
    /* A pixel of the ground in the box's shadow, one lit, and one of the tinted box. */
    GLubyte px[3][4];
    p_glReadPixels(x + 44, y + 22, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px[0]);
    p_glReadPixels(x + 8, y + 10, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px[1]);
    p_glReadPixels(x + 32, y + 40, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px[2]);
    printf("%-16s %-4s", names[panel], use_fbo ? "fbo" : "copy");
    for (int k = 0; k < 3; k++) printf("  %s", kind(px[k]));
    printf("  err 0x%x\n", p_glGetError());
  }
  p_glFinish();

  p_glDeleteFramebuffersEXT(1, &fbo);
  p_glDeleteTextures(2, maps);
  p_glDeleteBuffers(2, vbo);
  p_glDeleteLists(list, 2);
  printf("%-36s err 0x%x\n", "deleted", p_glGetError());
  if (argc > 1) {
    FILE *f = fopen(argv[1], "wb");
    if (!f) return 3;
    fprintf(f, "P6\n%d %d\n255\n", W, H);
    for (int yy = H - 1; yy >= 0; yy--)
      for (int xx = 0; xx < W; xx++) fwrite(buffer + 4 * (yy * W + xx), 1, 3, f);
    if (fclose(f) != 0) return 3;
  }
  destroy(ctx);
  dlclose(lib);
  return 0;
}
