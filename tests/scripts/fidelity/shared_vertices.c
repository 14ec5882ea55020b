/* A display list whose glBegin/glEnd repeats vertices, called three times: the second
 * call draws it indexed, each distinct vertex once (pipeline::emulate::shared_vertices).
 * Smooth, flat, then smooth again, as triangles and as a closed line strip, against
 * Mesa's own lists. 64x32 window. */
#include <GL/gl.h>

glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glOrtho(0, 64, 0, 32, -1, 1);
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glClearColor(0.1, 0.1, 0.1, 1);
glClear(GL_COLOR_BUFFER_BIT);
glNewList(1, GL_COMPILE);
glBegin(GL_TRIANGLES);
glColor3f(1, 0, 0);
glVertex2f(1, 1);
glColor3f(0, 1, 0);
glVertex2f(9, 1);
glColor3f(0, 0, 1);
glVertex2f(9, 9);
glColor3f(1, 0, 0);
glVertex2f(1, 1);
glColor3f(0, 0, 1);
glVertex2f(9, 9);
glColor3f(1, 1, 0);
glVertex2f(1, 9);
glColor3f(0, 1, 0);
glVertex2f(9, 1);
glColor3f(1, 0, 1);
glVertex2f(17, 1);
glColor3f(0, 0, 1);
glVertex2f(9, 9);
glEnd();
glBegin(GL_LINE_STRIP);
glColor3f(1, 1, 1);
glVertex2f(1.5, 12.5);
glColor3f(0, 1, 1);
glVertex2f(17.5, 12.5);
glColor3f(1, 1, 1);
glVertex2f(1.5, 12.5);
glColor3f(0, 1, 1);
glVertex2f(17.5, 12.5);
glEnd();
glEndList();
glShadeModel(GL_SMOOTH);
glCallList(1);
glTranslatef(20, 0, 0);
glShadeModel(GL_FLAT);
glCallList(1);
glTranslatef(20, 0, 0);
glShadeModel(GL_SMOOTH);
glCallList(1);
glTranslatef(-40, 16, 0);
glShadeModel(GL_FLAT);
glCallList(1);
