/* State set and read back: every glGet form, glIsEnabled and the per-object getters,
 * across lighting, texturing, texgen, per-fragment state, fog, clip planes, client arrays
 * and display lists, with glPushAttrib/glPopAttrib around changes. One line per query;
 * floats to 5 significant digits. Run on Mesa's OSMesa and on fixedfunc's library, the
 * outputs must be the same.
 *
 * usage: state */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>

static void ints(const char *what, GLenum pname, int n) {
  GLint v[16] = {0};
  glGetIntegerv(pname, v);
  printf("%-28s", what);
  for (int i = 0; i < n; i++) printf(" %d", v[i]);
  printf("  err 0x%x\n", glGetError());
}

static void floats(const char *what, GLenum pname, int n) {
  GLfloat v[16] = {0};
  glGetFloatv(pname, v);
  printf("%-28s", what);
  for (int i = 0; i < n; i++) printf(" %.5g", v[i]);
  printf("  err 0x%x\n", glGetError());
}

static void bools(const char *what, GLenum pname, int n) {
  GLboolean v[16] = {0};
  glGetBooleanv(pname, v);
  printf("%-28s", what);
  for (int i = 0; i < n; i++) printf(" %d", v[i]);
  printf("  err 0x%x\n", glGetError());
}

static void doubles(const char *what, GLenum pname, int n) {
  GLdouble v[16] = {0};
  glGetDoublev(pname, v);
  printf("%-28s", what);
  for (int i = 0; i < n; i++) printf(" %.5g", v[i]);
  printf("  err 0x%x\n", glGetError());
}

static void enabled(const char *what, GLenum cap) {
  GLboolean on = glIsEnabled(cap);
  printf("%-28s %d  err 0x%x\n", what, on, glGetError());
}

static void fv(const char *what, const GLfloat *v, int n) {
  printf("%-28s", what);
  for (int i = 0; i < n; i++) printf(" %.5g", v[i]);
  printf("  err 0x%x\n", glGetError());
}

int main(void) {
  static GLubyte buffer[32 * 24 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 32, 24)) return 1;
  GLfloat v[16];

  /* Defaults. */
  ints("viewport", GL_VIEWPORT, 4);
  ints("scissor box", GL_SCISSOR_BOX, 4);
  ints("matrix mode", GL_MATRIX_MODE, 1);
  floats("current color", GL_CURRENT_COLOR, 4);
  ints("current color (int)", GL_CURRENT_COLOR, 4);
  floats("current normal", GL_CURRENT_NORMAL, 3);
  bools("depth writemask", GL_DEPTH_WRITEMASK, 1);
  ints("depth func", GL_DEPTH_FUNC, 1);
  doubles("depth range", GL_DEPTH_RANGE, 2);
  ints("max lights", GL_MAX_LIGHTS, 1);
  ints("max texture units", GL_MAX_TEXTURE_UNITS, 1);
  ints("max clip planes", GL_MAX_CLIP_PLANES, 1);
  ints("max modelview depth", GL_MAX_MODELVIEW_STACK_DEPTH, 1);
  ints("max attrib depth", GL_MAX_ATTRIB_STACK_DEPTH, 1);
  ints("shade model", GL_SHADE_MODEL, 1);
  ints("front face", GL_FRONT_FACE, 1);
  ints("stencil writemask", GL_STENCIL_WRITEMASK, 1);
  ints("unpack alignment", GL_UNPACK_ALIGNMENT, 1);
  enabled("dither", GL_DITHER);
  enabled("lighting", GL_LIGHTING);
  enabled("vertex array", GL_VERTEX_ARRAY);

  /* Transform. */
  glMatrixMode(GL_PROJECTION);
  glOrtho(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(1, 2, 3);
  glScalef(2, 2, 2);
  glPushMatrix();
  floats("modelview", GL_MODELVIEW_MATRIX, 16);
  floats("projection", GL_PROJECTION_MATRIX, 16);
  ints("modelview depth", GL_MODELVIEW_STACK_DEPTH, 1);
  glPopMatrix();
  glViewport(2, 3, 20, 10);
  glDepthRange(0.25, 0.75);
  ints("viewport set", GL_VIEWPORT, 4);
  floats("depth range set", GL_DEPTH_RANGE, 2);

  /* Lighting. */
  GLfloat pos[] = {1, 2, 3, 0}, dif[] = {0.5f, 0.25f, 1, 1}, amb[] = {0.1f, 0.2f, 0.3f, 1};
  glLoadIdentity();
  glLightfv(GL_LIGHT1, GL_POSITION, pos);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, dif);
  glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 45);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 17.5f);
  glMaterialfv(GL_BACK, GL_EMISSION, dif);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT1);
  glColorMaterial(GL_BACK, GL_SPECULAR);
  glGetLightfv(GL_LIGHT1, GL_POSITION, v);
  fv("light1 position", v, 4);
  glGetLightfv(GL_LIGHT1, GL_DIFFUSE, v);
  fv("light1 diffuse", v, 4);
  glGetLightfv(GL_LIGHT1, GL_SPOT_CUTOFF, v);
  fv("light1 cutoff", v, 1);
  glGetMaterialfv(GL_FRONT, GL_SHININESS, v);
  fv("front shininess", v, 1);
  glGetMaterialfv(GL_BACK, GL_EMISSION, v);
  fv("back emission", v, 4);
  floats("light model ambient", GL_LIGHT_MODEL_AMBIENT, 4);
  bools("two side", GL_LIGHT_MODEL_TWO_SIDE, 1);
  ints("color material param", GL_COLOR_MATERIAL_PARAMETER, 1);
  ints("color material face", GL_COLOR_MATERIAL_FACE, 1);
  enabled("light1", GL_LIGHT1);

  /* Texturing. */
  static const GLubyte texels[4 * 4 * 4] = {255};
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, 7);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD_SIGNED);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2);
  GLfloat plane[] = {1, 0.5f, 0, 0.25f};
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_2D);
  ints("active texture", GL_ACTIVE_TEXTURE, 1);
  ints("binding 2d", GL_TEXTURE_BINDING_2D, 1);
  enabled("texture 2d (unit 1)", GL_TEXTURE_2D);
  enabled("texgen s (unit 1)", GL_TEXTURE_GEN_S);
  GLint iv[4];
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, iv);
  printf("%-28s %d  err 0x%x\n", "min filter", iv[0], glGetError());
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, iv);
  printf("%-28s %d  err 0x%x\n", "wrap s", iv[0], glGetError());
  /* GL 1.2's level range and LOD clamps: floats rounded to levels, negatives and NaN
   * refused, kept through glPushAttrib(GL_TEXTURE_BIT). */
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1.7f);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, iv);
  printf("%-28s %d  err 0x%x\n", "base level (1.7)", iv[0], glGetError());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, -1);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, iv);
  printf("%-28s %d  err 0x%x\n", "max level (-1)", iv[0], glGetError());
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0.0f / 0.0f);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, iv);
  printf("%-28s %d  err 0x%x\n", "base level (NaN)", iv[0], glGetError());
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 3e9f);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, iv);
  printf("%-28s %d  err 0x%x\n", "max level (3e9)", iv[0], glGetError());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 3);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 2.6f);
  glPushAttrib(GL_TEXTURE_BIT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 9);
  glPopAttrib();
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, iv);
  printf("%-28s %d  err 0x%x\n", "base level (popped)", iv[0], glGetError());
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, v);
  fv("min lod", v, 1);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, iv);
  printf("%-28s %d  err 0x%x\n", "max lod as int (2.6)", iv[0], glGetError());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1000);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -1000);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 1000);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, iv);
  printf("%-28s %d  err 0x%x\n", "level 0 width", iv[0], glGetError());
  glGetTexEnviv(GL_TEXTURE_ENV, GL_COMBINE_RGB, iv);
  printf("%-28s %d  err 0x%x\n", "combine rgb", iv[0], glGetError());
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_RGB_SCALE, v);
  fv("rgb scale", v, 1);
  glGetTexGenfv(GL_S, GL_OBJECT_PLANE, v);
  fv("object plane s", v, 4);
  glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, iv);
  printf("%-28s %d  err 0x%x\n", "texgen mode s", iv[0], glGetError());
  {
    /* Sizes of a level stored at the requested format's bits (RGBA4, RGB10_A2, LUMINANCE16). */
    GLint bound, bits[3];
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    const GLenum formats[3] = {GL_RGBA4, GL_RGB10_A2, GL_LUMINANCE16};
    for (int f = 0; f < 3; f++) {
      glBindTexture(GL_TEXTURE_2D, 900 + f);
      glTexImage2D(GL_TEXTURE_2D, 0, formats[f], 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &bits[0]);
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_ALPHA_SIZE, &bits[1]);
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_LUMINANCE_SIZE, &bits[2]);
      printf("%-28s r%d a%d l%d  err 0x%x\n", "stored bits", bits[0], bits[1], bits[2], glGetError());
    }
    glBindTexture(GL_TEXTURE_2D, bound);
  }
  glHint(GL_GENERATE_MIPMAP_HINT, GL_NICEST);
  ints("generate mipmap hint", GL_GENERATE_MIPMAP_HINT, 1);
  ints("render mode", GL_RENDER_MODE, 1);
  /* The state of selection, feedback and evaluators before any of their calls. */
  ints("name stack depth", GL_NAME_STACK_DEPTH, 1);
  ints("selection buffer size", GL_SELECTION_BUFFER_SIZE, 1);
  ints("feedback buffer size", GL_FEEDBACK_BUFFER_SIZE, 1);
  ints("feedback buffer type", GL_FEEDBACK_BUFFER_TYPE, 1);
  floats("map1 grid domain", GL_MAP1_GRID_DOMAIN, 2);
  ints("map1 grid segments", GL_MAP1_GRID_SEGMENTS, 1);
  doubles("map2 grid domain", GL_MAP2_GRID_DOMAIN, 4);
  bools("map2 grid segments", GL_MAP2_GRID_SEGMENTS, 2);
  /* SAMPLE_COVERAGE_INVERT, which Mesa also takes as a capability. */
  glEnable(GL_SAMPLE_COVERAGE_INVERT);
  enabled("enable coverage invert", GL_SAMPLE_COVERAGE_INVERT);
  bools("coverage invert", GL_SAMPLE_COVERAGE_INVERT, 1);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_SAMPLE_COVERAGE_INVERT);
  glPopAttrib();
  enabled("after an enable-bit pop", GL_SAMPLE_COVERAGE_INVERT);
  glSampleCoverage(1.0f, GL_FALSE);
  /* Vector parameters through the scalar forms: (param, 0, 0, 0), as Mesa takes them;
   * glLighti's and glLightModeli's colours mapped as integers, glFogi's and glTexEnvi's
   * taken as numbers; an eye plane carried by the inverse modelview. */
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glTranslatef(1, 2, 3);
  glLightf(GL_LIGHT5, GL_DIFFUSE, 0.5f);
  glGetLightfv(GL_LIGHT5, GL_DIFFUSE, v);
  fv("lightf diffuse", v, 4);
  glLighti(GL_LIGHT5, GL_AMBIENT, 3);
  glGetLightfv(GL_LIGHT5, GL_AMBIENT, v);
  fv("lighti ambient", v, 4);
  glLightf(GL_LIGHT5, GL_POSITION, 2.0f);
  glGetLightfv(GL_LIGHT5, GL_POSITION, v);
  fv("lightf position", v, 4);
  glLighti(GL_LIGHT5, GL_SPOT_DIRECTION, 2);
  glGetLightfv(GL_LIGHT5, GL_SPOT_DIRECTION, v);
  fv("lighti spot direction", v, 3);
  glFogi(GL_FOG_COLOR, 2);
  glGetFloatv(GL_FOG_COLOR, v);
  fv("fogi color", v, 4);
  glFogf(GL_FOG_COLOR, 0.25f);
  glGetFloatv(GL_FOG_COLOR, v);
  fv("fogf color", v, 4);
  glLightModeli(GL_LIGHT_MODEL_AMBIENT, 1);
  glGetFloatv(GL_LIGHT_MODEL_AMBIENT, v);
  fv("lightmodeli ambient", v, 4);
  glLightModelf(GL_LIGHT_MODEL_AMBIENT, 0.5f);
  glGetFloatv(GL_LIGHT_MODEL_AMBIENT, v);
  fv("lightmodelf ambient", v, 4);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 2);
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, v);
  fv("texenvi color", v, 4);
  glTexGenf(GL_S, GL_OBJECT_PLANE, 2);
  glGetTexGenfv(GL_S, GL_OBJECT_PLANE, v);
  fv("texgenf object plane", v, 4);
  glTexGeni(GL_T, GL_EYE_PLANE, 3);
  glGetTexGenfv(GL_T, GL_EYE_PLANE, v);
  fv("texgeni eye plane", v, 4);
  glPointParameterf(GL_POINT_DISTANCE_ATTENUATION, 2);
  glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, v);
  fv("pointparameterf attenuation", v, 3);
  glPopMatrix();
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 2.5f);
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, v);
  fv("lod bias", v, 1);
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS, 1.0f);
  printf("%-28s err 0x%x\n", "lod bias on TEXTURE_ENV", glGetError());
  glGetFloatv(GL_MAX_TEXTURE_LOD_BIAS, v);
  fv("max lod bias", v, 1);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.0f);
  glActiveTexture(GL_TEXTURE0);
  enabled("texture 2d (unit 0)", GL_TEXTURE_2D);

  /* Per-fragment state, fog, clip planes. */
  glPushAttrib(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_FOG_BIT | GL_ENABLE_BIT);
  glAlphaFunc(GL_GEQUAL, 0.5f);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_BLEND);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 2);
  glFogf(GL_FOG_END, 8);
  glEnable(GL_FOG);
  ints("alpha func", GL_ALPHA_TEST_FUNC, 1);
  floats("alpha ref", GL_ALPHA_TEST_REF, 1);
  ints("blend src, dst", GL_BLEND_SRC, 1);
  ints("blend dst", GL_BLEND_DST, 1);
  ints("fog mode", GL_FOG_MODE, 1);
  floats("fog start", GL_FOG_START, 1);
  ints("attrib depth", GL_ATTRIB_STACK_DEPTH, 1);
  glPopAttrib();
  ints("blend dst popped", GL_BLEND_DST, 1);
  enabled("blend popped", GL_BLEND);
  enabled("fog popped", GL_FOG);
  ints("depth func popped", GL_DEPTH_FUNC, 1);
  bools("depth mask popped", GL_DEPTH_WRITEMASK, 1);
  ints("alpha func popped", GL_ALPHA_TEST_FUNC, 1);
  GLdouble eq[] = {1, 0, 0, 0.5}, back[4];
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(1, 0, 0);
  glClipPlane(GL_CLIP_PLANE2, eq);
  glEnable(GL_CLIP_PLANE2);
  glGetClipPlane(GL_CLIP_PLANE2, back);
  printf("%-28s %.5g %.5g %.5g %.5g  err 0x%x\n", "clip plane 2", back[0], back[1], back[2],
         back[3], glGetError());
  enabled("clip plane 2", GL_CLIP_PLANE2);
  glScissor(1, 2, 3, 4);
  ints("scissor set", GL_SCISSOR_BOX, 4);

  /* Client state and lists. */
  static const GLfloat verts[6] = {0};
  glVertexPointer(2, GL_FLOAT, 8, verts);
  glEnableClientState(GL_VERTEX_ARRAY);
  glClientActiveTexture(GL_TEXTURE1);
  glTexCoordPointer(3, GL_SHORT, 0, verts);
  enabled("vertex array", GL_VERTEX_ARRAY);
  ints("vertex array size", GL_VERTEX_ARRAY_SIZE, 1);
  ints("vertex array stride", GL_VERTEX_ARRAY_STRIDE, 1);
  ints("client active texture", GL_CLIENT_ACTIVE_TEXTURE, 1);
  ints("texcoord array type", GL_TEXTURE_COORD_ARRAY_TYPE, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  ints("pack alignment", GL_PACK_ALIGNMENT, 1);
  glListBase(5);
  ints("list base", GL_LIST_BASE, 1);
  glNewList(3, GL_COMPILE);
  ints("list index", GL_LIST_INDEX, 1);
  ints("list mode", GL_LIST_MODE, 1);
  glEndList();

  /* Texture names: generated, bound, deleted (a bound name reverts to 0). */
  GLuint names[3];
  glGenTextures(3, names);
  printf("%-28s %u %u %u  err 0x%x\n", "generated names", names[0], names[1], names[2],
         glGetError());
  printf("%-28s %d\n", "is texture before bind", glIsTexture(names[1]));
  glBindTexture(GL_TEXTURE_2D, names[1]);
  printf("%-28s %d\n", "is texture after bind", glIsTexture(names[1]));
  ints("binding after bind", GL_TEXTURE_BINDING_2D, 1);
  glDeleteTextures(2, names);
  ints("binding after delete", GL_TEXTURE_BINDING_2D, 1);
  printf("%-28s %d\n", "is texture after delete", glIsTexture(names[1]));
  glGenTextures(1, names);
  printf("%-28s %u  err 0x%x\n", "next generated name", names[0], glGetError());
  glGenTextures(-1, names);
  printf("%-28s err 0x%x\n", "glGenTextures(-1)", glGetError());

  /* Buffer bindings. */
  GLuint vbo[2];
  glGenBuffers(2, vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo[1]);
  glBufferData(GL_ARRAY_BUFFER, 64, NULL, GL_STATIC_DRAW);
  glVertexPointer(3, GL_FLOAT, 0, (const GLvoid *)16);
  ints("array buffer binding", GL_ARRAY_BUFFER_BINDING, 1);
  ints("vertex array binding", GL_VERTEX_ARRAY_BUFFER_BINDING, 1);
  ints("element buffer binding", GL_ELEMENT_ARRAY_BUFFER_BINDING, 1);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  ints("array buffer unbound", GL_ARRAY_BUFFER_BINDING, 1);
  ints("vertex array binding kept", GL_VERTEX_ARRAY_BUFFER_BINDING, 1);

  /* A draw from arrays leaves the current colour as glColor set it (Mesa). */
  static const GLfloat tri3[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  static const GLubyte cols[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255};
  glVertexPointer(3, GL_FLOAT, 0, tri3);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, cols);
  glEnableClientState(GL_COLOR_ARRAY);
  glColor4f(0.25f, 0.5f, 0.75f, 1);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  floats("current color after arrays", GL_CURRENT_COLOR, 4);
  glDisableClientState(GL_COLOR_ARRAY);

  /* Errors of the getters. */
  ints("unknown pname", 0x1234, 1);
  enabled("unknown cap", 0x1234);
  glGetLightfv(GL_LIGHT0 + 8, GL_DIFFUSE, v);
  printf("%-28s err 0x%x\n", "light 8", glGetError());
  glGetMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, v);
  printf("%-28s err 0x%x\n", "material front and back", glGetError());
  glBegin(GL_POINTS);
  glGetFloatv(GL_CURRENT_COLOR, v);
  glEnd();
  printf("%-28s err 0x%x\n", "glGet inside glBegin", glGetError());

  OSMesaDestroyContext(ctx);
  return 0;
}
