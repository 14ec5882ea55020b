/* State and error answers where Mesa 22.3's OSMesa differs from a first reading of the
 * specification, one printed line per check: the call or the state read, its values and
 * glGetError after it. Run on Mesa's OSMesa and on fixedfunc's library, the two outputs
 * must be the same.
 *
 * Mesa deviations pinned here: glMultiDrawArrays and glMultiDrawElements whose first count
 * is 0 draw nothing (multi_draw_first_empty).
 *
 * usage: mesa_answers OUT.ppm */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stdio.h>
#include "report.h"

/* glPopAttrib restores the draw buffer (COLOR_BUFFER_BIT), the read buffer
 * (PIXEL_MODE_BIT) and the list base (LIST_BIT). Mesa sets the buffer again only when its
 * context copy (the last value set, on any framebuffer) differs from the saved one: a draw
 * buffer the framebuffer bound then cannot take is left out silently, a read buffer is
 * INVALID_OPERATION. GENERATE_MIPMAP_HINT is not restored by Mesa's pop, though
 * GL 1.4 puts it in HINT_BIT: the check pins Mesa's answer. */
static void attribute_groups(void) {
  GLuint fb;
  glGenFramebuffers(1, &fb);
  glDrawBuffer(GL_FRONT);
  glReadBuffer(GL_FRONT);
  glPushAttrib(GL_COLOR_BUFFER_BIT | GL_PIXEL_MODE_BIT);
  glDrawBuffer(GL_BACK);
  glReadBuffer(GL_BACK);
  glPopAttrib();
  err("pop COLOR_BUFFER|PIXEL_MODE");
  ints("draw buffer after pop", GL_DRAW_BUFFER);
  ints("read buffer after pop", GL_READ_BUFFER);
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glDrawBuffer(GL_BACK);
  glReadBuffer(GL_BACK);
  glPopAttrib();
  ints("draw buffer after COLOR_BUFFER pop", GL_DRAW_BUFFER);
  ints("read buffer after COLOR_BUFFER pop", GL_READ_BUFFER);
  glReadBuffer(GL_FRONT);
  glPushAttrib(GL_COLOR_BUFFER_BIT | GL_PIXEL_MODE_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glDrawBuffer(GL_NONE);
  glPopAttrib();
  err("pop window FRONT over an FBO");
  ints("fbo draw buffer", GL_DRAW_BUFFER);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glPushAttrib(GL_PIXEL_MODE_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glPushAttrib(GL_PIXEL_MODE_BIT);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glReadBuffer(GL_NONE);
  glPopAttrib();
  err("pop window read FRONT over an FBO");
  glPopAttrib();
  ints("fbo draw buffer", GL_DRAW_BUFFER);
  ints("fbo read buffer", GL_READ_BUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fb);
  ints("window draw buffer", GL_DRAW_BUFFER);
  glListBase(3);
  glPushAttrib(GL_LIST_BIT);
  glListBase(9);
  glPopAttrib();
  ints("list base after pop", GL_LIST_BASE);
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPushAttrib(GL_LIST_BIT);
  glListBase(7);
  glPopAttrib();
  glEndList();
  glCallList(list);
  ints("list base after a listed pop", GL_LIST_BASE);
  glListBase(0);
  glPushAttrib(GL_HINT_BIT);
  glHint(GL_GENERATE_MIPMAP_HINT, GL_FASTEST);
  glHint(GL_TEXTURE_COMPRESSION_HINT, GL_FASTEST);
  glHint(GL_FOG_HINT, GL_NICEST);
  glPopAttrib();
  ints("mipmap hint after pop (kept)", GL_GENERATE_MIPMAP_HINT);
  ints("compression hint after pop", GL_TEXTURE_COMPRESSION_HINT);
  ints("fog hint after pop", GL_FOG_HINT);
  glHint(GL_GENERATE_MIPMAP_HINT, GL_DONT_CARE);
}

/* glTexSubImage at a level outside [0, the target's highest] is INVALID_VALUE, checked
 * after the target and before the format, a missing image or the region. */
static void sub_image_levels(void) {
  static GLubyte texels[4 * 4 * 4 * 4];
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexSubImage1D(GL_TEXTURE_1D, -1, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  err("TexSubImage1D level -1");
  glTexSubImage1D(GL_TEXTURE_1D, 15, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  err("TexSubImage1D level 15");
  glTexSubImage1D(GL_TEXTURE_1D, 14, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  err("TexSubImage1D level 14 (no image)");
  glTexSubImage1D(GL_TEXTURE_2D, -1, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  err("TexSubImage1D bad target, level -1");
  glTexSubImage2D(GL_TEXTURE_2D, -1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  err("TexSubImage2D level -1");
  glTexSubImage2D(GL_TEXTURE_2D, 20, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  err("TexSubImage2D level 20");
  glTexSubImage2D(GL_TEXTURE_2D, -1, 0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, texels);
  err("TexSubImage2D level -1, bad format");
  glTexSubImage2D(GL_TEXTURE_2D, -1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, texels);
  err("TexSubImage2D level -1, bad pair");
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, -1, 1, 0x1234, GL_UNSIGNED_BYTE, texels);
  err("TexSubImage2D width -1, bad format");
  glTexSubImage2D(GL_TEXTURE_2D, 1, 9, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  err("TexSubImage2D no image, bad offset");
  glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 15, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                  texels);
  err("TexSubImage2D cube face level 15");
  glTexSubImage3D(GL_TEXTURE_3D, 12, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  err("TexSubImage3D level 12");
  glTexSubImage3D(GL_TEXTURE_3D, -1, 0, 0, 0, 1, 1, 1, 0x1234, GL_UNSIGNED_BYTE, texels);
  err("TexSubImage3D level -1, bad format");
  glTexSubImage3D(GL_TEXTURE_3D, 11, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  err("TexSubImage3D level 11 (no image)");
}

/* n = 0 reads no name: a NULL array is no error. glAreTexturesResident answers FALSE
 * when either array is NULL. */
static void empty_name_arrays(void) {
  glDeleteTextures(0, NULL);
  err("glDeleteTextures(0, NULL)");
  glPrioritizeTextures(0, NULL, NULL);
  err("glPrioritizeTextures(0, NULL, NULL)");
  glGenTextures(0, NULL);
  err("glGenTextures(0, NULL)");
  glDeleteBuffers(0, NULL);
  err("glDeleteBuffers(0, NULL)");
  glGenBuffers(0, NULL);
  err("glGenBuffers(0, NULL)");
  glDeleteLists(1, 0);
  err("glDeleteLists(1, 0)");
  glCallLists(0, GL_UNSIGNED_BYTE, NULL);
  err("glCallLists(0, UNSIGNED_BYTE, NULL)");
  glDeleteFramebuffers(0, NULL);
  err("glDeleteFramebuffers(0, NULL)");
  glGenFramebuffers(0, NULL);
  err("glGenFramebuffers(0, NULL)");
  glDeleteRenderbuffers(0, NULL);
  err("glDeleteRenderbuffers(0, NULL)");
  glGenRenderbuffers(0, NULL);
  err("glGenRenderbuffers(0, NULL)");
  glGenQueries(0, NULL);
  err("glGenQueries(0, NULL)");
  glDeleteQueries(0, NULL);
  err("glDeleteQueries(0, NULL)");
  printf("%-40s %d\n", "glAreTexturesResident(0, NULL, NULL)",
         glAreTexturesResident(0, NULL, NULL));
  err("glAreTexturesResident(0, NULL, NULL)");
  GLuint tex;
  glGenTextures(1, &tex);
  printf("%-40s %d\n", "glAreTexturesResident(1, name, NULL)",
         glAreTexturesResident(1, &tex, NULL));
  err("glAreTexturesResident(1, name, NULL)");
  glDeleteTextures(-1, NULL);
  err("glDeleteTextures(-1, NULL)");
  glDeleteTextures(1, &tex);
}

static void priority(const char *what, GLenum target) {
  GLfloat q = -7;
  glGetTexParameterfv(target, GL_TEXTURE_PRIORITY, &q);
  printf("%-40s %g  err 0x%x\n", what, q, glGetError());
}

/* glPrioritizeTextures of names glGenTextures gave but no bind has made textures: Mesa's
 * objects exist from glGenTextures, so the priority (clamped to [0, 1]) is read after the
 * first bind; a name never generated is left out. */
static void priorities_before_bind(void) {
  GLuint t[3], never = 77;
  GLclampf p[3] = {0.25f, 1.5f, -1.0f}, half = 0.5f;
  glGenTextures(3, t);
  glPrioritizeTextures(3, t, p);
  err("glPrioritizeTextures(generated names)");
  glPrioritizeTextures(1, &never, &half);
  err("glPrioritizeTextures(never generated)");
  glBindTexture(GL_TEXTURE_2D, t[0]);
  priority("priority 0.25 after bind", GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_1D, t[1]);
  priority("priority 1.5 after bind", GL_TEXTURE_1D);
  glBindTexture(GL_TEXTURE_CUBE_MAP, t[2]);
  priority("priority -1 after bind", GL_TEXTURE_CUBE_MAP);
  glBindTexture(GL_TEXTURE_2D, never);
  priority("never generated, after bind", GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_1D, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glDeleteTextures(3, t);
  glDeleteTextures(1, &never);
}

/* glGetTexImage in RED, GREEN or BLUE: the texture's components become R, G, B, A by
 * GL 1.5 Table 6.1 (L and I to R, A to A; missing colours 0), then the one asked for is
 * packed (§6.1.4). Mesa answers; only a depth texture refuses them (INVALID_OPERATION). */
static void one_colour_tex_images(void) {
  static const GLubyte texels[2 * 4] = {10, 20, 30, 40, 250, 128, 0, 255};
  static const GLenum bases[] = {GL_RGBA,  GL_RGB,       GL_LUMINANCE,
                                 GL_ALPHA, GL_INTENSITY, GL_LUMINANCE_ALPHA};
  static const GLenum formats[] = {GL_RED, GL_GREEN, GL_BLUE};
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  for (int b = 0; b < 6; b++) {
    glTexImage2D(GL_TEXTURE_2D, 0, bases[b], 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    for (int f = 0; f < 3; f++) {
      GLubyte u[2] = {7, 7};
      GLfloat v[2] = {-7, -7};
      glGetTexImage(GL_TEXTURE_2D, 0, formats[f], GL_UNSIGNED_BYTE, u);
      GLenum ub = glGetError();
      glGetTexImage(GL_TEXTURE_2D, 0, formats[f], GL_FLOAT, v);
      char what[48];
      snprintf(what, sizeof what, "GetTexImage base 0x%x in 0x%x", bases[b], formats[f]);
      printf("%-40s %d %d %.9g %.9g  err 0x%x 0x%x\n", what, u[0], u[1], v[0], v[1], ub,
             glGetError());
    }
  }
  GLubyte u[2] = {7, 7};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_UNSIGNED_BYTE, u);
  err("GetTexImage of a depth texture in RED");
  glBindTexture(GL_TEXTURE_2D, 0);
  glDeleteTextures(1, &tex);
}

/* An array pointer into a buffer object since deleted: the array's buffer binding reverts
 * to 0 (GL 1.5 §2.9.1) and Mesa keeps the offset, which glGetPointerv answers (also after
 * a client attribute pop). Drawing from it is left out: Mesa reads the offset as an
 * address in the program's memory (0x8: a crash); the layer reads nothing there. */
static void pointer_into_deleted_buffer(void) {
  GLuint b;
  void *p = (void *)7;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, 64, NULL, GL_STATIC_DRAW);
  glVertexPointer(2, GL_FLOAT, 0, (void *)8);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glDeleteBuffers(1, &b);
  ints("vertex array buffer after delete", GL_VERTEX_ARRAY_BUFFER_BINDING);
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  printf("%-40s %p  err 0x%x\n", "vertex pointer after delete", p, glGetError());
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glVertexPointer(2, GL_FLOAT, 0, NULL);
  glPopClientAttrib();
  glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
  printf("%-40s %p  err 0x%x\n", "vertex pointer after pop", p, glGetError());
  glVertexPointer(4, GL_FLOAT, 0, NULL);
}

/* With no buffer object bound, which error each buffer call gives for a bad parameter
 * name or range: Mesa checks glGetBufferPointerv's parameter name and glMapBuffer's access
 * (INVALID_ENUM) before the binding, the other calls the binding (INVALID_OPERATION)
 * first; a bad target is INVALID_ENUM before either. */
static void buffer_check_order(void) {
  void *p;
  GLint i;
  GLubyte d[8] = {0};
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glGetBufferPointerv(GL_ARRAY_BUFFER, 0x1234, &p);
  err("GetBufferPointerv(bad pname), unbound");
  glGetBufferPointerv(0x1234, GL_BUFFER_MAP_POINTER, &p);
  err("GetBufferPointerv(bad target), unbound");
  glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &p);
  err("GetBufferPointerv(MAP_POINTER), unbound");
  glGetBufferParameteriv(GL_ARRAY_BUFFER, 0x1234, &i);
  err("GetBufferParameteriv(bad pname), unbound");
  glMapBuffer(GL_ARRAY_BUFFER, 0x1234);
  err("MapBuffer(bad access), unbound");
  glUnmapBuffer(GL_ARRAY_BUFFER);
  err("UnmapBuffer, unbound");
  glBufferSubData(GL_ARRAY_BUFFER, -1, 4, d);
  err("BufferSubData(offset -1), unbound");
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, -1, d);
  err("GetBufferSubData(size -1), unbound");
}

/* glDrawArrays and glMultiDrawArrays with a first element below 0: no error (GL 1.5
 * defines none, Mesa raises none); a count below 0 is still INVALID_VALUE, a bad mode
 * INVALID_ENUM. What Mesa then draws is its vertex fetch past the array (the index taken
 * as unsigned), not pointer + first · stride; the layer draws nothing, so only the
 * errors are compared here. */
static void negative_first(void) {
  static const GLfloat v[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  GLint first[2] = {-1, 0};
  GLsizei count[2] = {3, 3};
  glVertexPointer(2, GL_FLOAT, 0, v + 1);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, -1, 3);
  err("DrawArrays(first -1, count 3)");
  glDrawArrays(GL_TRIANGLES, -1, 0);
  err("DrawArrays(first -1, count 0)");
  glDrawArrays(GL_TRIANGLES, -1, -1);
  err("DrawArrays(first -1, count -1)");
  glDrawArrays(0x1234, -1, 3);
  err("DrawArrays(bad mode, first -1)");
  glMultiDrawArrays(GL_TRIANGLES, first, count, 2);
  err("MultiDrawArrays(first {-1, 0})");
  glDisableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(4, GL_FLOAT, 0, NULL);
}

/* Lit pixels of the 8×8 window (red above 0), then the window cleared. */
static void lit(const char *what) {
  GLubyte px[8 * 8 * 4];
  int n = 0;
  glReadPixels(0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, px);
  for (int i = 0; i < 8 * 8; i++) n += px[4 * i] != 0;
  printf("%-40s lit %d  err 0x%x\n", what, n, glGetError());
  glClear(GL_COLOR_BUFFER_BIT);
}

/* glMultiDrawArrays and glMultiDrawElements whose first count is 0 draw nothing at all on
 * Mesa 22.3, whatever the later counts (a Mesa deviation from GL 1.5 §2.8, which draws
 * each list as glDrawArrays would); a later count of 0, or a first count of 1, does not
 * stop the others. A display list keeps the non-empty draws and draws them. */
static void multi_draw_first_empty(void) {
  static const GLfloat v[4][2] = {{0.5f, 0.5f}, {7.5f, 0.5f}, {7.5f, 7.5f}, {0.5f, 7.5f}};
  static const GLushort ix[4] = {0, 1, 2, 3};
  const GLvoid *lists[2] = {ix, ix};
  GLint first[3] = {0, 0, 1};
  GLsizei empty_first[3] = {0, 4, 2}, empty_second[3] = {4, 0, 2}, one_first[3] = {1, 4, 2};
  glVertexPointer(2, GL_FLOAT, 0, v);
  glEnableClientState(GL_VERTEX_ARRAY);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glMultiDrawArrays(GL_LINE_STRIP, first, empty_first, 3);
  lit("MultiDrawArrays counts {0, 4, 2}");
  glMultiDrawArrays(GL_LINE_STRIP, first, empty_second, 3);
  lit("MultiDrawArrays counts {4, 0, 2}");
  glMultiDrawArrays(GL_LINE_STRIP, first, one_first, 3);
  lit("MultiDrawArrays counts {1, 4, 2}");
  glMultiDrawElements(GL_LINE_STRIP, empty_first, GL_UNSIGNED_SHORT, lists, 2);
  lit("MultiDrawElements counts {0, 4}");
  glMultiDrawElements(GL_LINE_STRIP, empty_second, GL_UNSIGNED_SHORT, lists, 2);
  lit("MultiDrawElements counts {4, 0}");
  glNewList(1, GL_COMPILE);
  glMultiDrawArrays(GL_LINE_STRIP, first, empty_first, 3);
  glEndList();
  glCallList(1);
  lit("list of MultiDrawArrays {0, 4, 2}");
  glDeleteLists(1, 1);
  glDisableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(4, GL_FLOAT, 0, NULL);
}

int main(int argc, char **argv) {
  OSMesaContext ctx;
  GLubyte *buf = open_window(&ctx, 8, 8);
  if (!buf) return 1;
  attribute_groups();
  sub_image_levels();
  empty_name_arrays();
  priorities_before_bind();
  one_colour_tex_images();
  pointer_into_deleted_buffer();
  buffer_check_order();
  negative_first();
  multi_draw_first_empty();
  return finish(argc > 1 ? argv[1] : "/dev/null", ctx, buf, 8, 8);
}
