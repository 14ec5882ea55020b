/* glMultiDrawArrays and glMultiDrawElements on both paths: a 4x3 grid of coloured
 * vertices drawn as strips from client arrays, as index lists given as compound literals,
 * as offsets into an element-array buffer, and compiled into a display list. 48x32
 * window. */
#include <GL/gl.h>
#include <GL/glext.h>

glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glOrtho(0, 48, 0, 32, -1, 1);
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glClearColor(0.1, 0.1, 0.1, 1);
glClear(GL_COLOR_BUFFER_BIT);
glVertexPointer(2, GL_FLOAT, 0, (GLfloat[]){1, 1, 5, 1, 9, 1, 13, 1, 1, 7, 5, 7, 9, 7, 13, 7, 1, 13, 5, 13, 9, 13, 13, 13});
glColorPointer(3, GL_FLOAT, 0, (GLfloat[]){1, 0, 0, 0.78, 0.2, 0, 0.59, 0.39, 0, 0.39, 0.59, 0, 0, 1, 0, 0, 0.78, 0.2, 0, 0.59, 0.39, 0, 0.39, 0.59, 0, 0, 1, 0.2, 0, 0.78, 0.39, 0, 0.59, 0.59, 0, 0.39});
glEnableClientState(GL_VERTEX_ARRAY);
glEnableClientState(GL_COLOR_ARRAY);

/* Vertices at pixel centres (a point on a pixel corner lands on either pixel). */
glTranslatef(0.5, 0.5, 0);

/* Lower left: the three rows as line strips, and two triangles. */
glMultiDrawArrays(GL_LINE_STRIP, (GLint[]){0, 4, 8}, (GLsizei[]){4, 4, 4}, 3);
glTranslatef(0, 16, 0);
glMultiDrawArrays(GL_TRIANGLES, (GLint[]){2, 5}, (GLsizei[]){3, 3}, 2);

/* Lower middle: the two strips between the rows, from index lists. */
glLoadIdentity();
glTranslatef(16.5, 0.5, 0);
glMultiDrawElements(GL_TRIANGLE_STRIP, (GLsizei[]){8, 8}, GL_UNSIGNED_SHORT, (const void *[]){(GLushort[]){0, 4, 1, 5, 2, 6, 3, 7}, (GLushort[]){4, 8, 5, 9, 6, 10, 7, 11}}, 2);

/* Upper middle: the same strips from an element-array buffer, given as offsets. */
glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 1);
glBufferData(GL_ELEMENT_ARRAY_BUFFER, 16, (GLubyte[]){0, 4, 1, 5, 2, 6, 3, 7, 4, 8, 5, 9, 6, 10, 7, 11}, GL_STATIC_DRAW);
glTranslatef(0, 16, 0);
glMultiDrawElements(GL_TRIANGLE_STRIP, (GLsizei[]){6, 8}, GL_UNSIGNED_BYTE, (const void *[]){(void *)0, (void *)8}, 2);
glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);

/* Right: a display list keeps the arrays as they were when it was compiled. */
glNewList(1, GL_COMPILE);
glMultiDrawElements(GL_TRIANGLE_FAN, (GLsizei[]){4, 4}, GL_UNSIGNED_BYTE, (const void *[]){(GLubyte[]){0, 1, 5, 4}, (GLubyte[]){6, 7, 11, 10}}, 2);
glEndList();
glDisableClientState(GL_COLOR_ARRAY);
glColor3f(1, 1, 1);
glLoadIdentity();
glTranslatef(32.5, 0.5, 0);
glCallList(1);
glTranslatef(0, 16, 0);
glMultiDrawArrays(GL_POINTS, (GLint[]){0, 8}, (GLsizei[]){4, 4}, 2);
glDisableClientState(GL_VERTEX_ARRAY);
