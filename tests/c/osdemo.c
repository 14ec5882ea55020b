/* The classic OSMesa demo: a lit red torus, green cone and blue sphere in ortho view,
 * rendered into the caller's buffer and written as a PPM. Geometry through immediate
 * mode (quad strips, triangle fans); no GLU.
 *
 * usage: osdemo OUT.ppm [WIDTH HEIGHT] */
#include <math.h>

#define GL_FUNCTIONS(X)                                                              \
  X(void, glBegin, (GLenum))                                                         \
  X(void, glEnd, (void))                                                             \
  X(void, glVertex3f, (GLfloat, GLfloat, GLfloat))                                   \
  X(void, glNormal3f, (GLfloat, GLfloat, GLfloat))                                   \
  X(void, glLightfv, (GLenum, GLenum, const GLfloat *))                              \
  X(void, glMaterialfv, (GLenum, GLenum, const GLfloat *))                           \
  X(void, glEnable, (GLenum))                                                        \
  X(void, glMatrixMode, (GLenum))                                                    \
  X(void, glLoadIdentity, (void))                                                    \
  X(void, glOrtho, (GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble))     \
  X(void, glClear, (GLbitfield))                                                     \
  X(void, glPushMatrix, (void))                                                      \
  X(void, glPopMatrix, (void))                                                       \
  X(void, glRotatef, (GLfloat, GLfloat, GLfloat, GLfloat))                           \
  X(void, glTranslatef, (GLfloat, GLfloat, GLfloat))                                 \
  X(void, glFinish, (void))                                                          \
  X(GLenum, glGetError, (void))

#include "gl_resolve.h"

#ifdef RESOLVE_WITH_PROC_ADDRESS
#define glBegin p_glBegin
#define glEnd p_glEnd
#define glVertex3f p_glVertex3f
#define glNormal3f p_glNormal3f
#define glLightfv p_glLightfv
#define glMaterialfv p_glMaterialfv
#define glEnable p_glEnable
#define glMatrixMode p_glMatrixMode
#define glLoadIdentity p_glLoadIdentity
#define glOrtho p_glOrtho
#define glClear p_glClear
#define glPushMatrix p_glPushMatrix
#define glPopMatrix p_glPopMatrix
#define glRotatef p_glRotatef
#define glTranslatef p_glTranslatef
#define glFinish p_glFinish
#define glGetError p_glGetError
#endif

static const float PI = 3.14159265358979f;

/* A torus around the z axis: tube radius r, ring radius R. */
static void torus(float r, float R, int sides, int rings) {
  for (int i = 0; i < rings; i++) {
    float a0 = 2 * PI * i / rings, a1 = 2 * PI * (i + 1) / rings;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= sides; j++) {
      float b = 2 * PI * j / sides;
      for (int k = 0; k < 2; k++) {
        float a = k ? a1 : a0;
        float nx = cosf(a) * cosf(b), ny = sinf(a) * cosf(b), nz = sinf(b);
        glNormal3f(nx, ny, nz);
        glVertex3f(cosf(a) * (R + r * cosf(b)), sinf(a) * (R + r * cosf(b)), r * sinf(b));
      }
    }
    glEnd();
  }
}

/* A cone along +z: base radius, height; side as a fan of quads, base as a fan. */
static void cone(float base, float height, int slices) {
  float slope = base / height, n = sqrtf(1 + slope * slope);
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= slices; i++) {
    float a = 2 * PI * i / slices;
    glNormal3f(cosf(a) / n, sinf(a) / n, slope / n);
    glVertex3f(base * cosf(a), base * sinf(a), 0);
    glVertex3f(0, 0, height);
  }
  glEnd();
  glBegin(GL_TRIANGLE_FAN);
  glNormal3f(0, 0, -1);
  glVertex3f(0, 0, 0);
  for (int i = slices; i >= 0; i--) {
    float a = 2 * PI * i / slices;
    glVertex3f(base * cosf(a), base * sinf(a), 0);
  }
  glEnd();
}

static void sphere(float radius, int slices, int stacks) {
  for (int i = 0; i < stacks; i++) {
    float t0 = PI * i / stacks - PI / 2, t1 = PI * (i + 1) / stacks - PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= slices; j++) {
      float p = 2 * PI * j / slices;
      for (int k = 0; k < 2; k++) {
        float t = k ? t0 : t1;
        float x = cosf(t) * cosf(p), y = cosf(t) * sinf(p), z = sinf(t);
        glNormal3f(x, y, z);
        glVertex3f(radius * x, radius * y, radius * z);
      }
    }
    glEnd();
  }
}

static void render(void) {
  GLfloat light_ambient[] = {0.0, 0.0, 0.0, 1.0};
  GLfloat light_diffuse[] = {1.0, 1.0, 1.0, 1.0};
  GLfloat light_specular[] = {1.0, 1.0, 1.0, 1.0};
  GLfloat light_position[] = {1.0, 1.0, 1.0, 0.0};
  GLfloat red_mat[] = {1.0, 0.2, 0.2, 1.0};
  GLfloat green_mat[] = {0.2, 1.0, 0.2, 1.0};
  GLfloat blue_mat[] = {0.2, 0.2, 1.0, 1.0};

  glLightfv(GL_LIGHT0, GL_AMBIENT, light_ambient);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, light_diffuse);
  glLightfv(GL_LIGHT0, GL_SPECULAR, light_specular);
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-2.5, 2.5, -2.5, 2.5, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);

  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glPushMatrix();
  glRotatef(20.0, 1.0, 0.0, 0.0);

  glPushMatrix();
  glTranslatef(-0.75, 0.5, 0.0);
  glRotatef(90.0, 1.0, 0.0, 0.0);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, red_mat);
  torus(0.275f, 0.85f, 20, 20);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(-0.75, -0.5, 0.0);
  glRotatef(270.0, 1.0, 0.0, 0.0);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, green_mat);
  cone(1.0f, 2.0f, 16);
  glPopMatrix();

  glPushMatrix();
  glTranslatef(0.75, 0.0, -1.0);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, blue_mat);
  sphere(1.0f, 20, 20);
  glPopMatrix();

  glPopMatrix();
  glFinish();
}

int main(int argc, char **argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s OUT.ppm [WIDTH HEIGHT]\n", argv[0]);
    return 2;
  }
  int w = argc > 3 ? atoi(argv[2]) : 400, h = argc > 3 ? atoi(argv[3]) : 400;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!ctx) {
    fprintf(stderr, "OSMesaCreateContextExt failed\n");
    return 1;
  }
  GLubyte *buffer = malloc((size_t)w * h * 4);
  if (!buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, w, h)) {
    fprintf(stderr, "OSMesaMakeCurrent failed\n");
    return 1;
  }
  resolve_gl();
  render();
  GLenum err = glGetError();
  if (err != GL_NO_ERROR) {
    fprintf(stderr, "GL error 0x%x\n", err);
    return 1;
  }
  int ok = write_ppm(argv[1], buffer, w, h);
  OSMesaDestroyContext(ctx);
  free(buffer);
  return ok ? 0 : 1;
}
