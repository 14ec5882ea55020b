/* glBlitFramebuffer on both paths: the window's scene (four quadrants, a grey ramp, a
 * triangle with depths 0.25 to 0.75 that writes stencil 5) copied into a 32x32 FBO scaled
 * NEAREST (63x47 onto 32x24: odd over even, no sample ties) and LINEAR (the ramp), its
 * depth and stencil copied too and shown there by a quad drawn with the depth test and
 * stencil EQUAL 5; then the FBO back onto the window flipped in x, flipped in y with
 * LINEAR, under the scissor test, scaled up with the EXT name, and its depth into the
 * window's lower left. 64x64 window with stencil. */
#include <GL/gl.h>
#include <GL/glext.h>

glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glOrtho(0, 64, 0, 64, -1, 1);
glMatrixMode(GL_MODELVIEW);
glLoadIdentity();
glClearColor(0.1, 0.1, 0.1, 1);
glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
glColor3f(1, 0, 0);
glRecti(0, 0, 32, 24);
glColor3f(0, 1, 0);
glRecti(32, 0, 64, 24);
glColor3f(0, 0, 1);
glRecti(0, 24, 32, 48);
glColor3f(1, 1, 0);
glRecti(32, 24, 64, 48);
glBegin(GL_QUADS);
glColor3f(0, 0, 0);
glVertex2i(0, 48);
glColor3f(1, 1, 1);
glVertex2i(64, 48);
glVertex2i(64, 64);
glColor3f(0, 0, 0);
glVertex2i(0, 64);
glEnd();
glEnable(GL_DEPTH_TEST);
glEnable(GL_STENCIL_TEST);
glStencilFunc(GL_ALWAYS, 5, 0xff);
glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
glBegin(GL_TRIANGLES);
glColor3f(1, 0, 1);
glVertex3f(4, 4, 0.5);
glVertex3f(60, 4, 0);
glVertex3f(4, 60, -0.5);
glEnd();
glDisable(GL_STENCIL_TEST);
glDisable(GL_DEPTH_TEST);

/* FBO 1: 32x32 RGBA8 and DEPTH24_STENCIL8 renderbuffers. */
glBindRenderbuffer(GL_RENDERBUFFER, 1);
glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 32, 32);
glBindRenderbuffer(GL_RENDERBUFFER, 2);
glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, 32, 32);
glBindFramebuffer(GL_FRAMEBUFFER, 1);
glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, 1);
glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 2);
glClearColor(0, 0, 0, 0);
glClear(GL_COLOR_BUFFER_BIT);
glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
glBlitFramebuffer(0, 0, 63, 47, 0, 0, 32, 24, GL_COLOR_BUFFER_BIT, GL_NEAREST);
glBlitFramebuffer(0, 48, 64, 64, 0, 24, 32, 32, GL_COLOR_BUFFER_BIT, GL_LINEAR);
glBlitFramebuffer(0, 0, 63, 63, 0, 0, 32, 32, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);

/* In the FBO: a cyan quad at depth 0.5 where the copied depth is farther and the copied
 * stencil is 5, over its lower right. */
glViewport(0, 0, 32, 32);
glMatrixMode(GL_PROJECTION);
glLoadIdentity();
glOrtho(0, 32, 0, 32, -1, 1);
glMatrixMode(GL_MODELVIEW);
glEnable(GL_DEPTH_TEST);
glEnable(GL_STENCIL_TEST);
glStencilFunc(GL_EQUAL, 5, 0xff);
glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
glColor3f(0, 1, 1);
glRecti(8, 0, 32, 16);
glDisable(GL_STENCIL_TEST);
glDisable(GL_DEPTH_TEST);

/* Back onto the window. */
glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
glBindFramebuffer(GL_READ_FRAMEBUFFER, 1);
glBlitFramebuffer(0, 0, 32, 32, 32, 0, 0, 32, GL_COLOR_BUFFER_BIT, GL_NEAREST);
glBlitFramebuffer(0, 0, 32, 32, 32, 64, 64, 32, GL_COLOR_BUFFER_BIT, GL_LINEAR);
glEnable(GL_SCISSOR_TEST);
glScissor(4, 36, 20, 20);
glBlitFramebuffer(0, 0, 32, 32, 0, 32, 32, 64, GL_COLOR_BUFFER_BIT, GL_NEAREST);
glDisable(GL_SCISSOR_TEST);
glBlitFramebufferEXT(0, 0, 7, 7, 40, 40, 56, 56, GL_COLOR_BUFFER_BIT, GL_LINEAR);
glBlitFramebuffer(0, 0, 32, 32, 0, 0, 32, 32, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
glBindFramebuffer(GL_FRAMEBUFFER, 0);
