/* Framebuffer objects on both paths: a scene drawn into a texture through an FBO with a
 * depth renderbuffer (the EXT names), a depth-only FBO drawing a shadow map into a depth
 * texture (draw and read buffer NONE), mipmaps generated from the rendered texture, and
 * the window drawing both textures; one draw with glDrawBuffer(GL_NONE) leaves the
 * window unchanged. 64x32 window. */
#include <GL/gl.h>
#include <GL/glext.h>

/* The colour texture and its FBO (EXT names). */
glBindTexture(GL_TEXTURE_2D, 1);
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, 1);
glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, 32, 32);
glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 1);
glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, 1, 0);
glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, 1);
glViewport(0, 0, 32, 32);
glClearColor(0.2, 0.2, 0.6, 1);
glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
glEnable(GL_DEPTH_TEST);
glBegin(GL_TRIANGLES);
glColor3f(1, 0, 0);
glVertex3f(-0.9, -0.9, -0.5);
glColor3f(1, 1, 0);
glVertex3f(0.6, -0.8, 0.5);
glColor3f(1, 0, 1);
glVertex3f(-0.2, 0.9, 0);
glColor3f(0, 1, 0);
glVertex3f(0.9, 0.9, -0.2);
glVertex3f(-0.8, 0.3, 0.3);
glColor3f(0, 1, 1);
glVertex3f(0.4, -0.6, -0.9);
glEnd();
glBindTexture(GL_TEXTURE_2D, 1);
glGenerateMipmapEXT(GL_TEXTURE_2D);

/* The depth-only FBO: a depth texture, no colour. */
glBindTexture(GL_TEXTURE_2D, 2);
glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 32, 32, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
glBindFramebuffer(GL_FRAMEBUFFER, 2);
glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 2, 0);
glDrawBuffer(GL_NONE);
glReadBuffer(GL_NONE);
glClear(GL_DEPTH_BUFFER_BIT);
glBegin(GL_TRIANGLES);
glVertex3f(-1, -1, -1);
glVertex3f(1, -1, 0);
glVertex3f(-1, 1, 1);
glEnd();

/* The window: the rendered texture (minified through its mipmaps) and the depth map. */
glBindFramebuffer(GL_FRAMEBUFFER, 0);
glViewport(0, 0, 64, 32);
glDisable(GL_DEPTH_TEST);
glClearColor(0.1, 0.1, 0.1, 1);
glClear(GL_COLOR_BUFFER_BIT);
glEnable(GL_TEXTURE_2D);
glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
glBindTexture(GL_TEXTURE_2D, 1);
glBegin(GL_QUADS);
glTexCoord2f(0, 0);
glVertex2f(-1, -1);
glTexCoord2f(1, 0);
glVertex2f(-0.5, -1);
glTexCoord2f(1, 1);
glVertex2f(-0.5, 1);
glTexCoord2f(0, 1);
glVertex2f(-1, 1);
glEnd();
glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
glBegin(GL_QUADS);
glTexCoord2f(0, 0);
glVertex2f(-0.5, -1);
glTexCoord2f(1, 0);
glVertex2f(-0.25, -1);
glTexCoord2f(1, 1);
glVertex2f(-0.25, -0.5);
glTexCoord2f(0, 1);
glVertex2f(-0.5, -0.5);
glEnd();
glBindTexture(GL_TEXTURE_2D, 2);
glBegin(GL_QUADS);
glTexCoord2f(0, 0);
glVertex2f(0, -1);
glTexCoord2f(1, 0);
glVertex2f(1, -1);
glTexCoord2f(1, 1);
glVertex2f(1, 1);
glTexCoord2f(0, 1);
glVertex2f(0, 1);
glEnd();
glDisable(GL_TEXTURE_2D);
/* Drawn with the window's draw buffer NONE: nothing reaches it. */
glDrawBuffer(GL_NONE);
glColor3f(1, 1, 1);
glRectf(-1, -1, 1, 1);
glDrawBuffer(GL_FRONT);
glDeleteFramebuffers(2, (GLuint[]){1, 2});
glDeleteRenderbuffers(1, (GLuint[]){1});
