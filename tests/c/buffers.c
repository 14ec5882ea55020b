/* Buffer objects (GL 1.5): six panels, each drawn through buffers — vertices and colours
 * interleaved in one buffer at offsets, an element array buffer of GL_UNSIGNED_SHORT
 * indices, glBufferSubData replacing part of a buffer, vertices written through
 * glMapBuffer, client memory again after glDeleteBuffers, glDrawRangeElements with an
 * index offset — then one line per error check (glGetError, glIsBuffer,
 * glGetBufferParameteriv).
 *
 * usage: buffers OUT.ppm */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl_resolve.h"

#define W 192
#define H 128

static void panel(int i) { glViewport((i % 3) * 64, (i / 3) * 64, 64, 64); }

static void report(const char *step) { printf("%-40s 0x%04x\n", step, (unsigned)glGetError()); }

/* One interleaved vertex: position, then an RGBA colour. */
struct vertex {
  GLfloat xyz[3];
  GLubyte rgba[4];
};

int main(int argc, char **argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s OUT.ppm\n", argv[0]);
    return 2;
  }
  static GLubyte buffer[W * H * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) return 1;
  resolve_gl();
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);

  GLuint names[4] = {0, 0, 0, 0};
  glGenBuffers(4, names);
  printf("glGenBuffers gave 4 distinct names: %d\n",
         names[0] && names[1] && names[2] && names[3] && names[0] != names[1] &&
             names[1] != names[2] && names[2] != names[3]);
  printf("glIsBuffer before binding: %d\n", glIsBuffer(names[0]));
  report("after glGenBuffers");

  /* 0: vertices and colours interleaved in one buffer, read through offsets. */
  static const struct vertex tri[] = {{{-0.9f, -0.9f, 0}, {255, 0, 0, 255}},
                                      {{0.9f, -0.9f, 0}, {0, 255, 0, 255}},
                                      {{0, 0.9f, 0}, {0, 0, 255, 255}}};
  panel(0);
  glBindBuffer(GL_ARRAY_BUFFER, names[0]);
  glBufferData(GL_ARRAY_BUFFER, sizeof tri, tri, GL_STATIC_DRAW);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, sizeof(struct vertex), (const GLvoid *)0);
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct vertex),
                 (const GLvoid *)offsetof(struct vertex, rgba));
  glDrawArrays(GL_TRIANGLES, 0, 3);
  report("panel 0: interleaved buffer");

  /* 1: a quad through an element array buffer of unsigned shorts (no colour array). */
  static const GLfloat quad[] = {-0.8f, -0.8f, 0.8f, -0.8f, 0.8f, 0.8f, -0.8f, 0.8f};
  static const GLushort quad_idx[] = {0, 1, 2, 0, 2, 3};
  panel(1);
  glDisableClientState(GL_COLOR_ARRAY);
  glColor3f(1, 1, 0);
  glBindBuffer(GL_ARRAY_BUFFER, names[1]);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
  glVertexPointer(2, GL_FLOAT, 0, (const GLvoid *)0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, names[2]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof quad_idx, quad_idx, GL_STATIC_DRAW);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, (const GLvoid *)0);
  report("panel 1: element array buffer");

  /* 2: glBufferSubData replaces the last two vertices of the quad: a triangle fan that
   * now ends in a lower-right notch. */
  static const GLfloat notch[] = {0, 0, -0.8f, 0.8f};
  panel(2);
  glColor3f(0, 1, 1);
  glBindBuffer(GL_ARRAY_BUFFER, names[1]);
  glBufferSubData(GL_ARRAY_BUFFER, 4 * sizeof(GLfloat), sizeof notch, notch);
  glVertexPointer(2, GL_FLOAT, 0, (const GLvoid *)0);
  glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, (const GLvoid *)0);
  report("panel 2: glBufferSubData");

  /* 3: vertices written through glMapBuffer into a store made with NULL data. */
  panel(3);
  glColor3f(1, 0, 1);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ARRAY_BUFFER, names[3]);
  glBufferData(GL_ARRAY_BUFFER, 8 * sizeof(GLfloat), NULL, GL_DYNAMIC_DRAW);
  GLfloat *mapped = glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
  printf("glMapBuffer gave a pointer: %d\n", mapped != NULL);
  if (mapped) {
    static const GLfloat diamond[] = {0, -0.9f, 0.9f, 0, 0, 0.9f, -0.9f, 0};
    memcpy(mapped, diamond, sizeof diamond);
  }
  printf("glUnmapBuffer: %d\n", glUnmapBuffer(GL_ARRAY_BUFFER));
  glVertexPointer(2, GL_FLOAT, 0, (const GLvoid *)0);
  glDrawArrays(GL_QUADS, 0, 4);
  report("panel 3: glMapBuffer");

  /* 4: the buffers deleted, client memory again. */
  static const GLfloat strip[] = {-0.9f, -0.5f, 0.9f, -0.5f, -0.9f, 0.5f, 0.9f, 0.5f};
  panel(4);
  glColor3f(1, 0.5f, 0);
  glDeleteBuffers(1, &names[3]);
  printf("glIsBuffer after delete: %d\n", glIsBuffer(names[3]));
  glVertexPointer(2, GL_FLOAT, 0, strip);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  report("panel 4: client memory after delete");

  /* 5: glDrawRangeElements, the indices at an offset in the element buffer, vertices
   * and colours from the first buffer. */
  static const GLushort tri_idx[] = {9, 9, 2, 1, 0};
  panel(5);
  glBindBuffer(GL_ARRAY_BUFFER, names[0]);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, sizeof(struct vertex), (const GLvoid *)0);
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct vertex),
                 (const GLvoid *)offsetof(struct vertex, rgba));
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, names[2]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof tri_idx, tri_idx, GL_STREAM_DRAW);
  glMatrixMode(GL_MODELVIEW);
  glScalef(0.6f, 0.6f, 1);
  glDrawRangeElements(GL_TRIANGLES, 0, 2, 3, GL_UNSIGNED_SHORT,
                      (const GLvoid *)(2 * sizeof(GLushort)));
  glLoadIdentity();
  report("panel 5: glDrawRangeElements at an offset");
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);

  /* Errors, each on its own. */
  glBindBuffer(GL_TEXTURE_2D, names[0]);
  report("glBindBuffer(GL_TEXTURE_2D)");
  glBufferData(GL_ARRAY_BUFFER, 16, NULL, GL_RGBA);
  report("glBufferData(usage GL_RGBA)");
  glBufferData(GL_ARRAY_BUFFER, -1, NULL, GL_STATIC_DRAW);
  report("glBufferData(size -1)");
  GLint size = -1, usage = -1;
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &size);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_USAGE, &usage);
  printf("GL_BUFFER_SIZE %d GL_BUFFER_USAGE 0x%04x\n", size, (unsigned)usage);
  report("glGetBufferParameteriv");
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_RGBA, &size);
  report("glGetBufferParameteriv(GL_RGBA)");
  glBufferSubData(GL_ARRAY_BUFFER, (GLintptr)sizeof tri - 4, 8, quad);
  report("glBufferSubData beyond the size");
  glBufferSubData(GL_ARRAY_BUFFER, -4, 4, quad);
  report("glBufferSubData(offset -4)");
  GLubyte back[4] = {0, 0, 0, 0};
  glGetBufferSubData(GL_ARRAY_BUFFER, (GLintptr)offsetof(struct vertex, rgba), 4, back);
  printf("glGetBufferSubData: %d %d %d %d\n", back[0], back[1], back[2], back[3]);
  report("glGetBufferSubData");
  printf("glUnmapBuffer of an unmapped buffer: %d\n", glUnmapBuffer(GL_ARRAY_BUFFER));
  report("glUnmapBuffer unmapped");
  printf("first glMapBuffer gave a pointer: %d\n",
         glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY) != NULL);
  report("first glMapBuffer");
  printf("second glMapBuffer gave a pointer: %d\n",
         glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY) != NULL);
  report("second glMapBuffer");
  glBufferSubData(GL_ARRAY_BUFFER, 0, 4, quad);
  report("glBufferSubData while mapped");
  /* Mesa draws from the mapped buffer (a small white triangle on panel 5). */
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, sizeof(struct vertex), (const GLvoid *)0);
  glColor3f(1, 1, 1);
  glScalef(0.3f, 0.3f, 1);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glLoadIdentity();
  report("glDrawArrays from a mapped buffer");
  glDisableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  report("glDrawArrays, the array disabled");
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED, &size);
  printf("GL_BUFFER_MAPPED %d\n", size);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS, &size);
  printf("GL_BUFFER_ACCESS mapped 0x%04x\n", (unsigned)size);
  printf("glUnmapBuffer: %d\n", glUnmapBuffer(GL_ARRAY_BUFFER));
  /* GL 1.5 keeps the last access; Mesa answers READ_WRITE once unmapped. */
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS, &size);
  printf("GL_BUFFER_ACCESS unmapped 0x%04x\n", (unsigned)size);
  report("glUnmapBuffer");
  glMapBuffer(GL_ARRAY_BUFFER, GL_RGBA);
  report("glMapBuffer(access GL_RGBA)");
  printf("glIsBuffer before delete: %d\n", glIsBuffer(names[0]));
  glDeleteBuffers(3, names);
  printf("glIsBuffer after delete: %d\n", glIsBuffer(names[0]));
  report("glDeleteBuffers");
  glBufferData(GL_ARRAY_BUFFER, 16, NULL, GL_STATIC_DRAW);
  report("glBufferData with buffer 0 bound");
  glUnmapBuffer(GL_ELEMENT_ARRAY_BUFFER);
  report("glUnmapBuffer with buffer 0 bound");
  glGenBuffers(-1, names);
  report("glGenBuffers(-1)");

  glFinish();
  int ok = write_ppm(argv[1], buffer, W, H);
  OSMesaDestroyContext(ctx);
  return ok ? 0 : 1;
}
