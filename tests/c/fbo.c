/* Framebuffer objects as the programs of 2005–2010 used them, through both the ARB/core
 * names and the EXT ones: names, binding, attachments of textures and renderbuffers,
 * completeness, the attachment and renderbuffer queries, glDrawBuffer/glReadBuffer, and
 * the errors of bad calls, one line each; then an image: a scene drawn into a texture
 * through an FBO (with a depth renderbuffer), read back from it, and drawn on the window
 * buffer with that texture. Run on Mesa's OSMesa and on fixedfunc's library, the printed
 * lines must be the same and the images match.
 *
 * usage: fbo [out.ppm] */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>
#include "report.h"

#define W 64
#define H 64

static void status(const char *what, GLenum target) {
  GLenum s = glCheckFramebufferStatus(target);
  printf("%-40s 0x%x  err 0x%x\n", what, s, glGetError());
}

static void attachment(const char *what, GLenum att, GLenum pname) {
  GLint v = -7;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, att, pname, &v);
  printf("%-40s %d  err 0x%x\n", what, v, glGetError());
}

static void renderbuffer(const char *what, GLenum pname) {
  GLint v = -7;
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, pname, &v);
  printf("%-40s %d  err 0x%x\n", what, v, glGetError());
}

static void quad(float x0, float y0, float x1, float y1, float z) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0); glVertex3f(x0, y0, z);
  glTexCoord2f(1, 0); glVertex3f(x1, y0, z);
  glTexCoord2f(1, 1); glVertex3f(x1, y1, z);
  glTexCoord2f(0, 1); glVertex3f(x0, y1, z);
  glEnd();
}

int main(int argc, char **argv) {
  static GLubyte buffer[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) return 1;

  /* The window buffer. */
  ints("framebuffer binding", GL_FRAMEBUFFER_BINDING);
  ints("read framebuffer binding", GL_READ_FRAMEBUFFER_BINDING);
  ints("renderbuffer binding", GL_RENDERBUFFER_BINDING);
  ints("draw buffer (window)", GL_DRAW_BUFFER);
  ints("read buffer (window)", GL_READ_BUFFER);
  ints("max color attachments", GL_MAX_COLOR_ATTACHMENTS);
  ints("max renderbuffer size", GL_MAX_RENDERBUFFER_SIZE);
  status("window status", GL_FRAMEBUFFER);
  glDrawBuffer(GL_BACK);
  err("draw buffer BACK (single-buffered)");
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  err("draw buffer COLOR_ATTACHMENT0 (window)");
  glDrawBuffer(GL_TEXTURE_2D);
  err("draw buffer TEXTURE_2D");
  glDrawBuffer(GL_FRONT_LEFT);
  ints("draw buffer FRONT_LEFT", GL_DRAW_BUFFER);
  glDrawBuffer(GL_NONE);
  ints("draw buffer NONE", GL_DRAW_BUFFER);
  glDrawBuffer(GL_FRONT);
  glReadBuffer(GL_BACK);
  err("read buffer BACK");
  glReadBuffer(GL_NONE);
  err("read buffer NONE (window)");
  ints("read buffer after NONE", GL_READ_BUFFER);
  glReadBuffer(GL_FRONT);

  /* Names. */
  GLuint fb[3] = {0}, rb[2] = {0}, tex[3] = {0};
  glGenFramebuffers(2, fb);
  glGenRenderbuffers(2, rb);
  glGenTextures(3, tex);
  printf("%-40s %u %u %u %u\n", "names", fb[0], fb[1], rb[0], rb[1]);
  printf("%-40s %d %d\n", "is framebuffer before bind", glIsFramebuffer(fb[0]),
         glIsRenderbuffer(rb[0]));
  glGenFramebuffers(-1, fb + 2);
  err("gen framebuffers -1");
  glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
  printf("%-40s %d\n", "is framebuffer after bind", glIsFramebuffer(fb[0]));
  ints("framebuffer binding", GL_FRAMEBUFFER_BINDING);
  ints("read framebuffer binding", GL_READ_FRAMEBUFFER_BINDING);
  ints("draw buffer (fbo)", GL_DRAW_BUFFER);
  ints("read buffer (fbo)", GL_READ_BUFFER);
  status("empty fbo", GL_FRAMEBUFFER);
  status("empty fbo, read target", GL_READ_FRAMEBUFFER);
  glCheckFramebufferStatus(GL_TEXTURE_2D);
  err("status of TEXTURE_2D");
  glBindFramebuffer(GL_TEXTURE_2D, fb[0]);
  err("bind TEXTURE_2D");
  glDrawBuffer(GL_FRONT);
  err("draw buffer FRONT (fbo)");
  glDrawBuffer(GL_COLOR_ATTACHMENT1);
  ints("draw buffer COLOR_ATTACHMENT1", GL_DRAW_BUFFER);
  glDrawBuffer(GL_COLOR_ATTACHMENT0 + 8);
  err("draw buffer COLOR_ATTACHMENT8");
  glDrawBuffer(GL_COLOR_ATTACHMENT0);

  /* A texture without an image, then with one. */
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 0);
  err("attach texture without image");
  status("texture without image", GL_FRAMEBUFFER);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W, H, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  status("rgba8 texture", GL_FRAMEBUFFER);
  attachment("color type", GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
  attachment("color name", GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME);
  attachment("color level", GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL);
  attachment("depth type (none)", GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
  attachment("depth name (none)", GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME);
  attachment("bad pname", GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D);
  attachment("bad attachment", GL_TEXTURE_2D, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);

  /* Attachment errors. */
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 77, 0);
  err("attach unknown texture");
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], -1);
  err("attach level -1");
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 40);
  err("attach level 40");
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_1D, tex[0], 0);
  err("attach with textarget 1D");
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_TEXTURE_2D, GL_TEXTURE_2D, tex[0], 0);
  err("attach to TEXTURE_2D");
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + 8, GL_TEXTURE_2D, tex[0], 0);
  err("attach to COLOR_ATTACHMENT8");
  glFramebufferTexture2D(GL_TEXTURE_2D, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 0);
  err("attach on target TEXTURE_2D");
  status("still complete", GL_FRAMEBUFFER);

  /* Renderbuffers. */
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, W, H);
  err("storage with none bound");
  glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
  printf("%-40s %d\n", "is renderbuffer after bind", glIsRenderbuffer(rb[0]));
  ints("renderbuffer binding", GL_RENDERBUFFER_BINDING);
  renderbuffer("width before storage", GL_RENDERBUFFER_WIDTH);
  renderbuffer("format before storage", GL_RENDERBUFFER_INTERNAL_FORMAT);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_TEXTURE_2D, W, H);
  err("storage of TEXTURE_2D");
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, -1, H);
  err("storage width -1");
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 20000, H);
  err("storage width 20000");
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, W, H);
  err("storage depth24");
  renderbuffer("width", GL_RENDERBUFFER_WIDTH);
  renderbuffer("height", GL_RENDERBUFFER_HEIGHT);
  renderbuffer("internal format", GL_RENDERBUFFER_INTERNAL_FORMAT);
  renderbuffer("depth size", GL_RENDERBUFFER_DEPTH_SIZE);
  renderbuffer("red size", GL_RENDERBUFFER_RED_SIZE);
  renderbuffer("bad pname", GL_TEXTURE_2D);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, rb[0]);
  err("attach renderbuffer, target TEXTURE_2D");
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 55);
  err("attach unknown renderbuffer");
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[0]);
  err("attach depth renderbuffer");
  status("rgba8 + depth24", GL_FRAMEBUFFER);
  attachment("depth type", GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
  attachment("depth name", GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME);
  ints("depth bits (fbo)", GL_DEPTH_BITS);
  ints("stencil bits (fbo)", GL_STENCIL_BITS);
  ints("red bits (fbo)", GL_RED_BITS);
  ints("alpha bits (fbo)", GL_ALPHA_BITS);

  /* A depth renderbuffer as the colour: incomplete. */
  glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT16, W, H);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[1]);
  status("depth16 as colour", GL_FRAMEBUFFER);
  /* A colour renderbuffer of another size: complete under ARB_framebuffer_object. */
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, W / 2, H / 2);
  status("rgba8 32x32 with depth 64x64", GL_FRAMEBUFFER);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, 0);
  status("depth only, draw buffer 0", GL_FRAMEBUFFER);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  status("depth only, draw buffer NONE", GL_FRAMEBUFFER);
  attachment("color type after detach", GL_COLOR_ATTACHMENT0,
             GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glReadBuffer(GL_COLOR_ATTACHMENT0);

  /* A luminance texture as the colour. */
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE8, W, H, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, NULL);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[1], 0);
  status("luminance8 texture", GL_FRAMEBUFFER);
  /* A depth texture as the depth, the shadow map's FBO. */
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, W, H, 0, GL_DEPTH_COMPONENT,
               GL_UNSIGNED_INT, NULL);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex[2], 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  status("depth texture only", GL_FRAMEBUFFER);
  attachment("depth texture type", GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
  attachment("depth texture name", GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glReadBuffer(GL_COLOR_ATTACHMENT0);

  /* Inside glBegin/glEnd. */
  glBegin(GL_TRIANGLES);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glEnd();
  err("bind inside begin/end");
  ints("binding after begin/end bind", GL_FRAMEBUFFER_BINDING);

  /* Deleting the bound framebuffer binds the window again. */
  glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
  glDeleteFramebuffers(1, &fb[1]);
  err("delete bound framebuffer");
  ints("binding after delete", GL_FRAMEBUFFER_BINDING);
  printf("%-40s %d\n", "is framebuffer after delete", glIsFramebuffer(fb[1]));
  glDeleteFramebuffers(-1, fb);
  err("delete -1");

  /* The EXT names: a name never generated binds (and is made) as in GL 1.x. */
  glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 42);
  err("bind EXT ungenerated 42");
  ints("binding EXT 42", GL_FRAMEBUFFER_BINDING_EXT);
  glBindFramebuffer(GL_FRAMEBUFFER, 43);
  err("bind ARB ungenerated 43");
  ints("binding 43", GL_FRAMEBUFFER_BINDING);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[0]);
  ints("draw binding after DRAW bind", GL_DRAW_FRAMEBUFFER_BINDING);
  ints("read binding after DRAW bind", GL_READ_FRAMEBUFFER_BINDING);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  ints("read binding after READ bind", GL_READ_FRAMEBUFFER_BINDING);
  status("read status of the window", GL_READ_FRAMEBUFFER);

  /* Drawing into the texture: a red quad in front of a green one behind it, then the
   * window shows the texture. */
  glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[0], 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[0]);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  status("render target", GL_FRAMEBUFFER);
  glViewport(0, 0, W, H);
  glClearColor(0.2f, 0.2f, 0.6f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glColor3f(1, 0, 0);
  quad(-0.75f, -0.75f, 0.25f, 0.25f, -0.5f);
  glColor3f(0, 1, 0);
  quad(-0.25f, -0.25f, 0.75f, 0.75f, 0.5f);
  GLubyte px[4] = {0};
  glReadPixels(W / 2 - 4, H / 2 - 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  printf("%-40s %d %d %d %d  err 0x%x\n", "fbo pixel at the overlap", px[0], px[1], px[2],
         px[3], glGetError());
  GLfloat z = -1;
  glReadPixels(W / 2 - 4, H / 2 - 4, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
  printf("%-40s %.4f  err 0x%x\n", "fbo depth at the overlap", z, glGetError());
  /* Copy a corner of the FBO's colour into a second texture. */
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, W, H, 0);
  err("copy from the fbo");
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ints("depth bits (window)", GL_DEPTH_BITS);
  ints("stencil bits (window)", GL_STENCIL_BITS);
  glDisable(GL_DEPTH_TEST);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  quad(-1, -1, 0, 1, 0);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  quad(0, -1, 1, 0, 0);
  glDisable(GL_TEXTURE_2D);
  err("drawn");
  glFinish();

  glDeleteRenderbuffers(2, rb);
  glDeleteFramebuffers(1, fb);
  glDeleteTextures(3, tex);
  err("deleted");
  if (argc > 1 && !write_ppm(argv[1], buffer, W, H)) return 3;
  OSMesaDestroyContext(ctx);
  return 0;
}
