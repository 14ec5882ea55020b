/* Occlusion queries (GL 1.5, ARB_occlusion_query, ARB_occlusion_query2) as programs of the
 * 2000s used them: count the samples of an object drawn behind, in front of, beside and
 * through the other tests (scissor, alpha, depth, stencil), through each kind of drawing
 * (immediate mode, client arrays, a display list, glDrawPixels, glBitmap, glCopyPixels,
 * points and lines), and the answers and errors of every query call. Run on Mesa's OSMesa
 * and on fixedfunc's library, the printed lines must be the same and the images match.
 *
 * usage: queries [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include "report.h"

#define W 64
#define H 64

/* Ends the active SAMPLES_PASSED query `q` and prints its count. */
static void count(const char *what, GLuint q) {
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint n = 12345;
  glGetQueryObjectuiv(q, GL_QUERY_RESULT, &n);
  GLuint ready = 7;
  glGetQueryObjectuiv(q, GL_QUERY_RESULT_AVAILABLE, &ready);
  printf("%-40s %u ready %u  err 0x%x\n", what, n, ready, glGetError());
}

static void query_int(const char *what, GLenum target, GLenum pname) {
  GLint v = -7;
  glGetQueryiv(target, pname, &v);
  printf("%-40s %d  err 0x%x\n", what, v, glGetError());
}

static void object_int(const char *what, GLuint id, GLenum pname) {
  GLint v = -7;
  glGetQueryObjectiv(id, pname, &v);
  printf("%-40s %d  err 0x%x\n", what, v, glGetError());
}

static void quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glVertex3f(x0, y0, z);
  glVertex3f(x1, y0, z);
  glVertex3f(x1, y1, z);
  glVertex3f(x0, y1, z);
  glEnd();
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "queries.ppm";
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  GLubyte *buffer = calloc(W * H, 4);
  if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) {
    fprintf(stderr, "no context\n");
    return 1;
  }
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, W, 0, H, 1, -1); /* window depth grows with z: z = -1 nearest */
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  /* State before any query. */
  query_int("counter bits, SAMPLES_PASSED", GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS);
  query_int("counter bits, ANY_SAMPLES_PASSED", GL_ANY_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS);
  query_int("current query, none", GL_SAMPLES_PASSED, GL_CURRENT_QUERY);
  GLuint q[4] = {0};
  glGenQueries(4, q);
  printf("%-40s %u %u %u %u  err 0x%x\n", "names", q[0], q[1], q[2], q[3], glGetError());
  printf("%-40s %d  err 0x%x\n", "generated, not begun: glIsQuery", glIsQuery(q[0]),
         glGetError());

  /* Counts. The first quad is drawn at depth 0; others in front or behind it. */
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.3f, 0.3f, 0.8f);
  quad(8, 8, 40, 40, 0);
  glBeginQuery(GL_SAMPLES_PASSED, q[0]);
  query_int("current query, active", GL_SAMPLES_PASSED, GL_CURRENT_QUERY);
  query_int("current query of ANY, SAMPLES active", GL_ANY_SAMPLES_PASSED, GL_CURRENT_QUERY);
  glColor3f(0.9f, 0.2f, 0.2f);
  quad(24, 24, 56, 56, 0.5f); /* behind: only the part beside the first quad passes */
  count("behind, partly hidden", q[0]);
  printf("%-40s %d  err 0x%x\n", "begun: glIsQuery", glIsQuery(q[0]), glGetError());
  glBeginQuery(GL_SAMPLES_PASSED, q[1]);
  glColor3f(0.2f, 0.9f, 0.2f);
  quad(16, 16, 32, 32, -0.5f); /* in front: all of it */
  count("in front", q[1]);
  glBeginQuery(GL_SAMPLES_PASSED, q[1]);
  quad(16, 16, 32, 32, 0.9f); /* hidden entirely */
  count("hidden, the same query again", q[1]);

  glBeginQuery(GL_SAMPLES_PASSED, q[2]);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 12, 12);
  glColor3f(0.8f, 0.8f, 0.2f);
  quad(0, 0, 64, 64, -0.9f);
  glDisable(GL_SCISSOR_TEST);
  count("scissored to 12x12", q[2]);

  glBeginQuery(GL_SAMPLES_PASSED, q[2]);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glColor4f(1, 1, 1, 0.25f);
  quad(0, 0, 64, 64, -0.9f); /* fails the alpha test */
  glDisable(GL_ALPHA_TEST);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  quad(44, 0, 64, 20, -0.9f); /* passes, writes no colour: still counted */
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  count("alpha-tested away, colour-masked", q[2]);

  glBeginQuery(GL_SAMPLES_PASSED, q[3]);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  quad(40, 40, 60, 60, -0.9f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glColor3f(0.9f, 0.5f, 0.1f);
  quad(30, 30, 64, 64, -0.9f); /* only inside the stencilled square */
  glDisable(GL_STENCIL_TEST);
  count("stencil mark, then through it", q[3]);

  /* Each kind of drawing. */
  GLuint k[6];
  glGenQueries(6, k);
  static const GLfloat tri[] = {2, 44, 18, 44, 2, 60};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, tri);
  glBeginQuery(GL_SAMPLES_PASSED, k[0]);
  glColor3f(0.6f, 0.2f, 0.7f);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  count("client-array triangle", k[0]);
  glDisableClientState(GL_VERTEX_ARRAY);

  glNewList(1, GL_COMPILE);
  glBeginQuery(GL_SAMPLES_PASSED, k[1]);
  glColor3f(0.2f, 0.7f, 0.7f);
  quad(44, 2, 62, 10, -0.95f);
  glEndQuery(GL_SAMPLES_PASSED);
  glEndList();
  err("list compiled");
  printf("%-40s %d  err 0x%x\n", "compiled, not run: glIsQuery", glIsQuery(k[1]), glGetError());
  glCallList(1);
  object_int("from a display list", k[1], GL_QUERY_RESULT);

  static GLubyte block[8 * 8 * 4];
  for (int i = 0; i < 8 * 8 * 4; i++) block[i] = (GLubyte)(i * 7);
  glBeginQuery(GL_SAMPLES_PASSED, k[2]);
  glRasterPos3f(2, 26, -0.95f);
  glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, block);
  glDrawPixels(0, 0, GL_RGBA, GL_UNSIGNED_BYTE, block);
  count("glDrawPixels 8x8", k[2]);

  static const GLubyte bits[8] = {0xff, 0x81, 0x81, 0x81, 0x81, 0x81, 0x81, 0xff};
  glBeginQuery(GL_SAMPLES_PASSED, k[3]);
  glColor3f(1, 1, 1);
  glRasterPos3f(12, 26, -0.95f);
  glBitmap(8, 8, 0, 0, 0, 0, bits);
  count("glBitmap outline 8x8", k[3]);

  glBeginQuery(GL_SAMPLES_PASSED, k[4]);
  glRasterPos3f(50, 26, -0.95f);
  glCopyPixels(8, 8, 6, 6, GL_COLOR);
  glClear(GL_STENCIL_BUFFER_BIT);
  count("glCopyPixels 6x6; glClear uncounted", k[4]);

  glBeginQuery(GL_ANY_SAMPLES_PASSED, k[5]);
  glPointSize(3);
  glBegin(GL_POINTS);
  glVertex3f(60.5f, 30.5f, -0.95f);
  glEnd();
  glBegin(GL_LINES);
  glVertex3f(2, 62.5f, -0.95f);
  glVertex3f(40, 62.5f, -0.95f);
  glEnd();
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  object_int("ANY_SAMPLES_PASSED, points and lines", k[5], GL_QUERY_RESULT);
  object_int("its QUERY_TARGET", k[5], GL_QUERY_TARGET);
  GLuint any = 77;
  glBeginQuery(GL_ANY_SAMPLES_PASSED, 90);
  quad(0, 0, 64, 64, 0.99f);
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  glGetQueryObjectuiv(90, GL_QUERY_RESULT, &any);
  printf("%-40s %u  err 0x%x\n", "ANY_SAMPLES_PASSED, a far quad", any, glGetError());

  /* Errors, each then checked. */
  GLint v = -7;
  glGenQueries(-1, q);
  err("glGenQueries(-1)");
  glDeleteQueries(-1, q);
  err("glDeleteQueries(-1)");
  glBeginQuery(GL_TEXTURE_2D, q[0]);
  err("begin, bad target");
  glBeginQuery(GL_SAMPLES_PASSED, 0);
  err("begin query 0");
  glEndQuery(GL_SAMPLES_PASSED);
  err("end, none active");
  glBeginQuery(GL_SAMPLES_PASSED, k[5]);
  err("begin, begun before as ANY");
  glGetQueryiv(GL_TEXTURE_2D, GL_CURRENT_QUERY, &v);
  err("glGetQueryiv bad target");
  glGetQueryiv(GL_SAMPLES_PASSED, GL_TEXTURE_2D, &v);
  err("glGetQueryiv bad pname");
  GLuint fresh[1];
  glGenQueries(1, fresh);
  glGetQueryObjectiv(fresh[0], GL_QUERY_RESULT, &v);
  err("result of a query never begun");
  glGetQueryObjectiv(fresh[0], GL_TEXTURE_2D, &v);
  err("... with a bad pname too");
  glGetQueryObjectiv(4000, GL_QUERY_RESULT, &v);
  err("result of no query");
  glGetQueryObjectiv(q[0], GL_TEXTURE_2D, &v);
  err("bad pname of a query");
  glBeginQuery(GL_SAMPLES_PASSED, 200);
  err("begin a name never generated");
  printf("%-40s %d  err 0x%x\n", "... is a query now", glIsQuery(200), glGetError());
  glBeginQuery(GL_SAMPLES_PASSED, 201);
  err("begin while one is active");
  glBeginQuery(GL_ANY_SAMPLES_PASSED, 202);
  err("begin ANY while SAMPLES is active");
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  err("end ANY while SAMPLES is active");
  glGetQueryObjectiv(200, GL_QUERY_RESULT, &v);
  err("result of the active query");
  glBegin(GL_POINTS);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
  glEnd();
  err("glGetQueryiv inside glBegin/glEnd");
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glPopAttrib();
  query_int("current after push/pop of attribs", GL_SAMPLES_PASSED, GL_CURRENT_QUERY);
  GLuint del = 200;
  glDeleteQueries(1, &del);
  err("delete the active query");
  query_int("current after deleting it", GL_SAMPLES_PASSED, GL_CURRENT_QUERY);
  glEndQuery(GL_SAMPLES_PASSED);
  err("... then end");
  printf("%-40s %d  err 0x%x\n", "deleted: glIsQuery", glIsQuery(200), glGetError());
  glDeleteQueries(4, q);
  err("delete four");
  printf("%-40s %d  err 0x%x\n", "deleted: glIsQuery(q0)", glIsQuery(q[0]), glGetError());
  GLuint again[2];
  glGenQueries(2, again);
  printf("%-40s %u %u  err 0x%x\n", "names after the deletes", again[0], again[1],
         glGetError());
  object_int("result of a deleted query", q[1], GL_QUERY_RESULT);

  glFinish();
  if (!write_ppm(out, buffer, W, H)) return 1;
  OSMesaDestroyContext(ctx);
  free(buffer);
  return 0;
}
