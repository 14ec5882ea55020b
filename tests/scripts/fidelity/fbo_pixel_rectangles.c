/* Pixel rectangles into a framebuffer object of another size than the window: glDrawPixels,
 * glBitmap and glCopyPixels at raster positions inside a 40x24 FBO, then the FBO texture
 * drawn in the 64x64 window. */
#include <GL/gl.h>
#include <GL/glext.h>
glBindTexture(GL_TEXTURE_2D, 1);
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 40, 24, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 1);
glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, 1, 0);
glViewport(0, 0, 40, 24);
glClearColor(0.1, 0.2, 0.3, 1);
glClear(GL_COLOR_BUFFER_BIT);
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glOrtho(0, 40, 0, 24, -1, 1);
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glRasterPos2i(3, 4);
glDrawPixels(4, 3, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){255,0,0,255, 0,255,0,255, 0,0,255,255, 255,255,0,255, 255,0,255,255, 0,255,255,255, 255,255,255,255, 128,0,0,255, 0,128,0,255, 0,0,128,255, 128,128,0,255, 0,128,128,255});
glPixelZoom(2, 3);
glRasterPos2i(20, 10);
glDrawPixels(4, 3, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){255,0,0,255, 0,255,0,255, 0,0,255,255, 255,255,0,255, 255,0,255,255, 0,255,255,255, 255,255,255,255, 128,0,0,255, 0,128,0,255, 0,0,128,255, 128,128,0,255, 0,128,128,255});
glPixelZoom(1, 1);
glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
glColor3f(1, 0.5, 0);
glRasterPos2i(30, 2);
glBitmap(8, 2, 0, 0, 0, 0, (GLubyte[]){0xA5, 0xFF});
glRasterPos2i(10, 15);
glCopyPixels(3, 4, 4, 3, GL_COLOR);
glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
glViewport(0, 0, 64, 64);
glClearColor(0, 0, 0, 1);
glClear(GL_COLOR_BUFFER_BIT);
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glEnable(GL_TEXTURE_2D);
glBindTexture(GL_TEXTURE_2D, 1);
glColor3f(1, 1, 1);
glBegin(GL_QUADS);
glTexCoord2f(0, 0); glVertex2f(-1, -1);
glTexCoord2f(1, 0); glVertex2f(0.25, -1);
glTexCoord2f(1, 1); glVertex2f(0.25, -0.25);
glTexCoord2f(0, 1); glVertex2f(-1, -0.25);
glEnd();
glDisable(GL_TEXTURE_2D);
glRasterPos2f(0.5, 0.5);
glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, (GLubyte[]){255,0,0,255, 0,255,0,255, 0,0,255,255, 255,255,255,255});
