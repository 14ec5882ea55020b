/* The accumulation buffer's five operations, each in its own 8-pixel column of a 64x32
 * window (the scissor box confines the scene, the accumulation and the return to it):
 * values out of range, negative, and the clear value clamped. Replayed with --accum on the
 * emulated path (Mesa's signed 16-bit arithmetic, ff::accum) and on the native path with
 * --backend osmesa (Mesa's own glAccum in OSMesa's window buffer). */
#include <GL/gl.h>

#define SCENE \
  glClear(GL_COLOR_BUFFER_BIT); \
  glBegin(GL_QUADS); \
  glColor4f(0, 0, 0.5, 1); glVertex2f(-1, -1); \
  glColor4f(1, 0, 0.5, 0.25); glVertex2f(1, -1); \
  glColor4f(1, 1, 0.5, 0.5); glVertex2f(1, 1); \
  glColor4f(0, 1, 0.5, 0.75); glVertex2f(-1, 1); \
  glEnd();

glClearColor(0.1, 0.2, 0.3, 0.4);
glClear(GL_COLOR_BUFFER_BIT);
glEnable(GL_SCISSOR_TEST);

/* 0: the clear value, clamped to [-1, 1] (1.5 → 1, -2 → -1), returned: negative → 0. */
glScissor(0, 0, 8, 32);
glClearAccum(0.5, -0.25, 1.5, -2);
glClear(GL_ACCUM_BUFFER_BIT);
glAccum(GL_RETURN, 1.0);

/* 1: LOAD then RETURN: the scene through 16 bits and back. */
glScissor(8, 0, 8, 32);
SCENE
glAccum(GL_LOAD, 1.0);
glClear(GL_COLOR_BUFFER_BIT);
glAccum(GL_RETURN, 1.0);

/* 2: two halves accumulated (a two-frame blur of one frame). */
glScissor(16, 0, 8, 32);
SCENE
glAccum(GL_LOAD, 0.5);
glAccum(GL_ACCUM, 0.5);
glAccum(GL_RETURN, 1.0);

/* 3: ADD past the top of the range. */
glScissor(24, 0, 8, 32);
SCENE
glAccum(GL_LOAD, 1.0);
glAccum(GL_ADD, 1.5);
glAccum(GL_RETURN, 1.0);

/* 4: MULT by a negative value, then ADD back into range. */
glScissor(32, 0, 8, 32);
SCENE
glAccum(GL_LOAD, 1.0);
glAccum(GL_MULT, -0.5);
glAccum(GL_ADD, 0.75);
glAccum(GL_RETURN, 1.0);

/* 5: RETURN scaled out of range (clamped to [0, 1]). */
glScissor(40, 0, 8, 32);
SCENE
glAccum(GL_LOAD, 0.25);
glAccum(GL_RETURN, 4.0);

/* 6: ACCUM of a negative weight, RETURN of 2. */
glScissor(48, 0, 8, 32);
SCENE
glAccum(GL_LOAD, 1.0);
glAccum(GL_ACCUM, -0.75);
glAccum(GL_RETURN, 2.0);

/* 7: RETURN through the colour mask (green and alpha kept as drawn). */
glScissor(56, 0, 8, 32);
glClearAccum(-0.5, 0.25, 0.75, 1);
glClear(GL_ACCUM_BUFFER_BIT);
SCENE
glAccum(GL_ADD, 0.125);
glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
glAccum(GL_RETURN, 1.0);
glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
glDisable(GL_SCISSOR_TEST);
