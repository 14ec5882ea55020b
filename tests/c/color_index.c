/* Colour-index state and multisample coverage in an RGBA context, as programs that set
 * them anyway do: glIndex* in and outside glBegin/glEnd and in lists, glClearIndex,
 * glIndexMask, glIndexPointer with glArrayElement, glSampleCoverage and the sample
 * enables; their conversions, errors, queries and attribute groups; and a frame drawn with
 * all of them set, which they must not change (RGBA buffers, no multisample buffers). Run
 * on Mesa's OSMesa and on fixedfunc's library, the printed lines must be the same and the
 * images match.
 *
 * Two Mesa 22.3 slips are left out of the printed lines: a glClearIndex compiled into a
 * display list sets the bits of the float as the index (4.0 becomes 1082130432), and
 * SAMPLE_COVERAGE_INVERT keeps the GLboolean as given (5 reads back as 5); the layer
 * stores the value and TRUE.
 *
 * usage: color_index [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"
#define W 32
#define H 32

static void f1(const char *what, GLenum p) {
  GLfloat v[4] = {-7, -7, -7, -7};
  glGetFloatv(p, v);
  printf("%-30s %g err %x\n", what, v[0], glGetError());
}

static void b1(const char *what, GLenum p) {
  GLboolean v[4] = {7, 7, 7, 7};
  glGetBooleanv(p, v);
  printf("%-30s %d err %x\n", what, v[0], glGetError());
}

static void index_state(void) {
  f1("index initial", GL_CURRENT_INDEX);
  ints("index initial as int", GL_CURRENT_INDEX);
  glIndexf(3.7f);
  f1("indexf 3.7", GL_CURRENT_INDEX);
  ints("index 3.7 as int", GL_CURRENT_INDEX);
  glIndexi(-5);
  f1("indexi -5", GL_CURRENT_INDEX);
  glIndexub(200);
  f1("indexub 200", GL_CURRENT_INDEX);
  glIndexs(-300);
  f1("indexs -300", GL_CURRENT_INDEX);
  glIndexd(1e10);
  f1("indexd 1e10", GL_CURRENT_INDEX);
  glIndexfv((GLfloat[]){2.5f});
  f1("indexfv 2.5", GL_CURRENT_INDEX);
  glIndexubv((GLubyte[]){17});
  f1("indexubv 17", GL_CURRENT_INDEX);
  glBegin(GL_POINTS);
  glIndexf(9);
  glVertex2f(0, 0);
  glIndexdv((GLdouble[]){10});
  glEnd();
  err("index inside glBegin");
  f1("index after pair", GL_CURRENT_INDEX);
  glNewList(1, GL_COMPILE);
  glIndexf(11);
  glIndexMask(0xF0);
  glEndList();
  f1("index after compile", GL_CURRENT_INDEX);
  glCallList(1);
  f1("index after list", GL_CURRENT_INDEX);
  ints("index mask from list", GL_INDEX_WRITEMASK);
  f1("clear index initial", GL_INDEX_CLEAR_VALUE);
  glClearIndex(2.6f);
  f1("clear index 2.6", GL_INDEX_CLEAR_VALUE);
  ints("clear index 2.6 as int", GL_INDEX_CLEAR_VALUE);
  glClearIndex(7);
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glClearIndex(50);
  glIndexMask(3);
  glPopAttrib();
  f1("pop clear index 7", GL_INDEX_CLEAR_VALUE);
  ints("pop index mask", GL_INDEX_WRITEMASK);
  glClearIndex(-1.5f);
  f1("clear index -1.5", GL_INDEX_CLEAR_VALUE);
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glPopAttrib();
  f1("pop clear index -1", GL_INDEX_CLEAR_VALUE);
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glClearIndex(50);
  glPopAttrib();
  f1("pop clear index -1 changed", GL_INDEX_CLEAR_VALUE);
  glIndexMask(0xFFFFFFFF);
  ints("index mask all", GL_INDEX_WRITEMASK);
  glPushAttrib(GL_CURRENT_BIT);
  glIndexf(100);
  glPopAttrib();
  f1("pop current index", GL_CURRENT_INDEX);
  b1("index mode", GL_INDEX_MODE);
  ints("index bits", GL_INDEX_BITS);

  static GLfloat data[8] = {0, 4, 8, 12, 16, 20, 24, 28};
  GLenum types[] = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT,
                    GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE};
  for (int t = 0; t < 8; t++) {
    glIndexPointer(types[t], 0, data);
    printf("index pointer type %x err %x\n", types[t], glGetError());
  }
  glIndexPointer(GL_FLOAT, -1, data);
  err("index pointer stride -1");
  glIndexPointer(GL_SHORT, 6, data + 1);
  ints("index array type", GL_INDEX_ARRAY_TYPE);
  ints("index array stride", GL_INDEX_ARRAY_STRIDE);
  void *p;
  glGetPointerv(GL_INDEX_ARRAY_POINTER, &p);
  printf("index pointer at %d\n", (int)((char *)p - (char *)data));
  glEnableClientState(GL_INDEX_ARRAY);
  ints("index array on", GL_INDEX_ARRAY);
  printf("index array is enabled %d\n", glIsEnabled(GL_INDEX_ARRAY));
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glIndexPointer(GL_FLOAT, 0, (void *)8);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  ints("index buffer binding", GL_INDEX_ARRAY_BUFFER_BINDING);
  glDeleteBuffers(1, &b);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDisableClientState(GL_INDEX_ARRAY);
  glIndexPointer(GL_INT, 0, data);
  glPopClientAttrib();
  ints("pop client index array", GL_INDEX_ARRAY);
  ints("pop client index type", GL_INDEX_ARRAY_TYPE);
  glInterleavedArrays(GL_V2F, 0, data);
  ints("interleaved index array", GL_INDEX_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glIndexPointer(GL_FLOAT, 0, data);
  glEnableClientState(GL_INDEX_ARRAY);
  glArrayElement(3);
  f1("index after element", GL_CURRENT_INDEX);
  glDisableClientState(GL_INDEX_ARRAY);
}

static void coverage_state(void) {
  f1("coverage initial", GL_SAMPLE_COVERAGE_VALUE);
  b1("invert initial", GL_SAMPLE_COVERAGE_INVERT);
  glSampleCoverage(0.3f, GL_TRUE);
  f1("coverage 0.3", GL_SAMPLE_COVERAGE_VALUE);
  b1("invert true", GL_SAMPLE_COVERAGE_INVERT);
  ints("coverage 0.3 as int", GL_SAMPLE_COVERAGE_VALUE);
  glSampleCoverage(1.7f, GL_FALSE);
  f1("coverage 1.7", GL_SAMPLE_COVERAGE_VALUE);
  glSampleCoverage(-1, GL_FALSE);
  f1("coverage -1", GL_SAMPLE_COVERAGE_VALUE);
  glSampleCoverage(NAN, GL_FALSE);
  f1("coverage NaN", GL_SAMPLE_COVERAGE_VALUE);
  glSampleCoverageARB(0.5f, GL_FALSE);
  f1("coverage ARB 0.5", GL_SAMPLE_COVERAGE_VALUE);
  glBegin(GL_POINTS);
  glSampleCoverage(0.2f, GL_FALSE);
  glEnd();
  err("coverage inside glBegin");
  glNewList(2, GL_COMPILE);
  glSampleCoverage(0.9f, GL_TRUE);
  glEndList();
  f1("coverage after compile", GL_SAMPLE_COVERAGE_VALUE);
  glCallList(2);
  f1("coverage after list", GL_SAMPLE_COVERAGE_VALUE);
  glPushAttrib(GL_MULTISAMPLE_BIT);
  glSampleCoverage(0.1f, GL_FALSE);
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glDisable(GL_MULTISAMPLE);
  glPopAttrib();
  f1("pop coverage", GL_SAMPLE_COVERAGE_VALUE);
  b1("pop invert", GL_SAMPLE_COVERAGE_INVERT);
  ints("pop alpha to coverage", GL_SAMPLE_ALPHA_TO_COVERAGE);
  ints("pop multisample", GL_MULTISAMPLE);
  glEnable(GL_SAMPLE_COVERAGE);
  glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  ints("sample coverage on", GL_SAMPLE_COVERAGE);
  printf("alpha to one is enabled %d\n", glIsEnabled(GL_SAMPLE_ALPHA_TO_ONE));
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_SAMPLE_COVERAGE);
  glDisable(GL_SAMPLE_ALPHA_TO_ONE);
  glPopAttrib();
  ints("pop enable sample coverage", GL_SAMPLE_COVERAGE);
  ints("pop enable alpha to one", GL_SAMPLE_ALPHA_TO_ONE);
  ints("sample buffers", GL_SAMPLE_BUFFERS);
}

/* A frame with every piece of that state set: RGBA drawing ignores the index, the mask and
 * the coverage. */
static void frame(void) {
  glClearColor(0.2f, 0.3f, 0.4f, 1);
  glClearIndex(9);
  glIndexMask(0);
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glSampleCoverage(0.25f, GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glIndexi(3); glColor4f(1, 0, 0, 0.2f); glVertex2f(-0.9f, -0.9f);
  glIndexi(5); glColor4f(0, 1, 0, 0.5f); glVertex2f(0.9f, -0.9f);
  glIndexi(7); glColor4f(0, 0, 1, 1); glVertex2f(0, 0.9f);
  glEnd();
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "color_index.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buf = calloc(W * H, 4);
  if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
  index_state();
  coverage_state();
  frame();
  glFinish();
  if (!write_ppm(out, buf, W, H)) return 1;
  OSMesaDestroyContext(ctx);
  free(buf);
  return 0;
}
