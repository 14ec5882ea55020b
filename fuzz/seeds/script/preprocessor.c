/* The dialect's preprocessor and immediate mode, in a few lines. */
#include <GL/gl.h>
#define SIZE 4
#define W SIZE
#ifdef W
#if 1
glViewport(0, 0, W, SIZE);
#elif defined(SIZE)
glViewport(0, 0, 1, 1);
#else
glViewport(0, 0, 2, 2);
#endif
#endif
#ifndef NOTHING
glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
#endif
#undef SIZE
glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
glMatrixMode(GL_PROJECTION);
glLoadMatrixf((GLfloat[]){1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
glEnable(GL_LIGHT0 + 1);
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){255, 0, 0, 255});
glBegin(GL_TRIANGLES);
glColor3f(1, 0, 0); glVertex3f(-1, -1, 0);
glTexCoord2f(0x1p-1, 1e0); glVertex3f(1, -1, 0);
glMultiTexCoord2f(GL_TEXTURE1, 0, 1); glVertex3f(0, 1, 0);
glEnd();
glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, readback_0);
